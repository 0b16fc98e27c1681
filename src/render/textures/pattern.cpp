#include "render/textures/pattern.h"

#include <array>
#include <cmath>
#include <cstdint>

#include "core/noise.h"
#include "render/textures/density_file.h"
#include "render/textures/fractal_patterns.h"
#include "render/textures/pigment.h"
#include "render/textures/surface_patterns.h"
#include "render/textures/pov_numbers.h"
#include "render/textures/tiling_pattern.h"

namespace glint::render {
namespace {

using scene::PatternKind;
using scene::PatternParams;
using scene::Warp;
using scene::WarpKind;

using pov_numbers::kHalfPi;
using pov_numbers::kSqrt3;
using pov_numbers::kSqrt3Half;
using pov_numbers::kTwoPi;
using pov_numbers::pov_int;
// ripples/waves: POV-Ray's number_of_waves has no upper limit; glint stores this many.
constexpr int kMaxWaves = 1024;

// POV-Ray's cycloidal(): sin(2 pi v) of v's fractional part, odd around 0.
double cycloidal(double v) {
    if (v >= 0.0) return std::sin(((v - std::floor(v)) * 50000.0) / 50000.0 * kTwoPi);
    return 0.0 - std::sin(((0.0 - (v + std::floor(0.0 - v))) * 50000.0) / 50000.0 * kTwoPi);
}

double triangle_wave(double v) {
    double offset = v >= 0.0 ? v - std::floor(v) : v + 1.0 + std::floor(std::fabs(v));
    return offset >= 0.5 ? 2.0 * (1.0 - offset) : 2.0 * offset;
}

// POV-Ray's CLIP_DENSITY: 1 - r inside [0, 1], 1 below, 0 above.
double clip_density(double r) {
    if (r < 0.0) return 1.0;
    if (r > 1.0) return 0.0;
    return 1.0 - r;
}

// POV-Ray's FLOOR macro (texture.h).
double pov_floor(double x) { return x >= 0.0 ? std::floor(x) : (0.0 - std::floor(0.0 - x) - 1.0); }

TurbulenceParams turb_params(const scene::Turbulence& t) {
    return TurbulenceParams{t.octaves, t.omega, t.lambda};
}

// Search_For_Turb: the classic turbulence written in the pattern (the importer keeps it as one
// ClassicTurbulence warp), or null.
const Warp* classic_turbulence(const PatternParams& params) {
    for (const Warp& w : params.warps)
        if (w.kind == WarpKind::ClassicTurbulence) return &w;
    return nullptr;
}

int noise_generator(const PatternParams& params, const PatternContext& ctx) {
    return params.noise_generator != 0 ? params.noise_generator : ctx.noise_generator;
}

// Initialize_Waves (texture.cpp): wave centres from dnoise along the x axis, frequencies from
// POV-Ray's table generator seeded with -560851967.
struct WaveTables {
    std::array<Vec3, kMaxWaves> source;
    std::array<double, kMaxWaves> frequency;
    WaveTables() {
        int32_t next_rand = -560851967;
        for (int i = 0; i < kMaxWaves; ++i) {
            source[i] = normalize(dnoise(Vec3(i, 0.0, 0.0)));
            next_rand =
                static_cast<int32_t>(static_cast<uint32_t>(next_rand) * 1812433253u + 12345u);
            frequency[i] =
                static_cast<double>((next_rand >> 16) & 0x7FFF) * 0.000030518509476 + 0.01;
        }
    }
};

const WaveTables& wave_tables() {
    static const WaveTables kTables;
    return kTables;
}

int wave_count(const PatternContext& ctx) { return std::clamp(ctx.number_of_waves, 1, kMaxWaves); }

// ---- Pattern functions (pattern.cpp), in POV-Ray's order of arithmetic. ----

double agate(const PatternParams& params, const Vec3& p, int gen) {
    const Warp* turb = classic_turbulence(params);
    TurbulenceParams tp = turb ? turb_params(turb->turbulence) : TurbulenceParams{};
    double turb_val = params.agate_turb * turbulence(p, tp, gen);
    double v = 0.5 * (cycloidal(1.3 * turb_val + 1.1 * p.z) + 1.0);
    if (v < 0.0) return 0.0;
    return std::pow(std::min(1.0, v), 0.77);
}

double boxed(const Vec3& p) {
    return clip_density(std::max(std::fabs(p.x), std::max(std::fabs(p.y), std::fabs(p.z))));
}

// The fractional part as POV-Ray's brick computes it: truncation, then +1 if negative.
double brick_frac(double v) {
    double f = v - static_cast<double>(pov_int(v));
    return f < 0.0 ? f + 1.0 : f;
}

double brick(const PatternParams& params, const Vec3& p) {
    const double fudge = kPovEpsilon + params.mortar;
    const double x = p.x + fudge, y = p.y + fudge, z = p.z + fudge;
    const Vec3& size = params.brick_size;
    const double mortar_w = params.mortar / size.x;
    const double mortar_h = params.mortar / size.y;
    const double mortar_d = params.mortar / size.z;
    if (brick_frac(y / size.y) <= mortar_h) return 0.0;  // horizontal mortar layers
    const double row = brick_frac((y / size.y) * 0.5);   // odd or even course
    if (brick_frac(x / size.x) <= mortar_w && row <= 0.5) return 0.0;
    if (brick_frac(x / size.x + 0.5) <= mortar_w && row > 0.5) return 0.0;
    if (brick_frac(z / size.z) <= mortar_d && row > 0.5) return 0.0;
    if (brick_frac(z / size.z + 0.5) <= mortar_d && row <= 0.5) return 0.0;
    return 1.0;
}

double cells(const Vec3& p) {
    int h = hash3d(pov_int(std::floor(p.x + kPovEpsilon)), pov_int(std::floor(p.y + kPovEpsilon)),
                   pov_int(std::floor(p.z + kPovEpsilon)));
    return std::min(pattern_random(static_cast<unsigned>(h)), 1.0);
}

double checker(const Vec3& p) {
    int v = pov_int(std::floor(p.x + kPovEpsilon) + std::floor(p.y + kPovEpsilon) +
                    std::floor(p.z + kPovEpsilon));
    return (v & 1) ? 1.0 : 0.0;
}

// The 81 cube offsets crackle and facets search: within a "3d knight move" (at most one
// coordinate of magnitude 2), in POV-Ray's order.
struct CubeOffsets {
    std::array<std::array<int, 3>, 81> d{};
    constexpr CubeOffsets() {
        int n = 0;
        for (int x = -2; x <= 2; ++x)
            for (int y = -2; y <= 2; ++y)
                for (int z = -2; z <= 2; ++z)
                    if ((x == 2 || x == -2) + (y == 2 || y == -2) + (z == 2 || z == -2) <= 1)
                        d[n++] = {x, y, z};
    }
};
constexpr CubeOffsets kCubeOffsets;

// fx + d without signed overflow at INT_MIN (huge coordinates).
int wrap_add(int a, int d) {
    return static_cast<int>(static_cast<unsigned>(a) + static_cast<unsigned>(d));
}

// IntPickInCube: the jittered feature point of lattice cube (x, y, z).
Vec3 cube_point(int x, int y, int z) {
    unsigned seed = static_cast<unsigned>(hash3d(x & 0xFFF, y & 0xFFF, z & 0xFFF));
    return {x + pattern_random(seed), y + pattern_random(seed + 1), z + pattern_random(seed + 2)};
}

double crackle_distance(const Vec3& d, double metric) {
    if (metric == 2) return d.x * d.x + d.y * d.y + d.z * d.z;
    if (metric == 1) return std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
    return std::pow(std::fabs(d.x), metric) + std::pow(std::fabs(d.y), metric) +
           std::pow(std::fabs(d.z), metric);
}

double crackle(const PatternParams& params, const Vec3& p, int gen) {
    const double metric = params.crackle_metric;
    const int fx = pov_int(std::floor(p.x - kPovEpsilon));
    const int fy = pov_int(std::floor(p.y - kPovEpsilon));
    const int fz = pov_int(std::floor(p.z - kPovEpsilon));
    Vec3 pts[81];
    for (int i = 0; i < 81; ++i) {
        const auto& o = kCubeOffsets.d[i];
        pts[i] = cube_point(wrap_add(fx, o[0]), wrap_add(fy, o[1]), wrap_add(fz, o[2]));
    }
    // The three smallest distances, kept as POV-Ray keeps them (ties resolve the same way).
    double m1 = crackle_distance(pts[0] - p, metric);
    double m2 = crackle_distance(pts[1] - p, metric);
    double m3 = crackle_distance(pts[2] - p, metric);
    int nearest = 0;
    if (m2 < m1) {
        std::swap(m1, m2);
        nearest = 1;
    }
    if (m3 < m1) {
        std::swap(m1, m3);
        nearest = 2;
    }
    if (m3 < m2) std::swap(m2, m3);
    for (int i = 3; i < 81; ++i) {
        double s = crackle_distance(pts[i] - p, metric);
        if (s < m1) {
            m3 = m2;
            m2 = m1;
            m1 = s;
            nearest = i;
        } else if (s < m2) {
            m3 = m2;
            m2 = s;
        } else if (s < m3) {
            m3 = s;
        }
    }
    const double offset = params.crackle_offset;
    if (offset != 0.0) {
        double add =
            metric == 2 ? offset * offset : (metric == 1 ? offset : std::pow(offset, metric));
        m1 += add;
        m2 += add;
        m3 += add;
    }
    const Vec3& form = params.crackle_form;
    double v;
    if (params.crackle_solid) {
        v = noise(pts[nearest], gen);
    } else if (metric == 2) {
        v = form.x * std::sqrt(m1) + form.y * std::sqrt(m2) + form.z * std::sqrt(m3);
    } else if (metric == 1) {
        v = form.x * m1 + form.y * m2 + form.z * m3;
    } else {
        v = form.x * std::pow(m1, 1.0 / metric) + form.y * std::pow(m2, 1.0 / metric) +
            form.z * std::pow(m3, 1.0 / metric);
    }
    return std::max(std::min(v, 1.), 0.);
}

double cylindrical(const Vec3& p) { return clip_density(std::sqrt(p.x * p.x + p.z * p.z)); }

double gradient(const PatternParams& params, const Vec3& p) {
    double r = dot(p, params.vector);
    return r > 1.0 ? std::fmod(r, 1.0) : r;
}

double granite(const Vec3& p, int gen) {
    double sum = 0.0, freq = 1.0;
    const Vec3 base = p * 4.0;
    for (int i = 0; i < 6; freq *= 2.0, ++i) {
        Vec3 q = base * freq;
        double t;
        if (gen == 1) {
            t = std::fabs(0.5 - noise(q, gen));
        } else {
            t = std::fabs(1.0 - 2.0 * noise(q, gen));
            if (t > 0.5) t = 0.5;
        }
        sum += t / freq;
    }
    return sum;
}

double hexagon(const Vec3& p) {
    constexpr double kXFactor = 0.5;          // each triangle is split in half for the grid
    constexpr double kZFactor = 0.866025404;  // sqrt(3)/2 as POV-Ray writes it
    double x = std::fabs(p.x);
    // Negative z is mapped so the pattern does not mirror across the x axis (6 rows high).
    double z = p.z < 0.0 ? 5.196152424 - std::fabs(p.z) : p.z;
    double xs = x / kXFactor, zs = z / kZFactor;
    xs -= std::floor(xs / 6.0) * 6.0;
    zs -= std::floor(zs / 6.0) * 6.0;
    // xs and zs are in [0, 6) but for huge or non-finite coordinates, where POV-Ray's int
    // conversion is undefined; keep the block indices inside the tables there.
    if (!(xs >= 0.0 && xs < 6.0)) xs = 0.0;
    if (!(zs >= 0.0 && zs < 6.0)) zs = 0.0;
    int xm = static_cast<int>(pov_floor(xs)) % 6;
    int zm = static_cast<int>(pov_floor(zs)) % 6;
    // Blocks 0/5 and 2/3 along x depend on zm only; blocks 1/4 are split by a diagonal.
    static constexpr int kOuter[6] = {0, 1, 1, 2, 2, 0};  // xm 0, 5
    static constexpr int kInner[6] = {2, 2, 0, 0, 1, 1};  // xm 2, 3
    static constexpr int kBelow[6] = {0, 2, 1, 0, 2, 1};  // xm 1, 4, under the diagonal
    static constexpr int kAbove[6] = {2, 1, 0, 2, 1, 0};  // xm 1, 4, over it
    switch (xm) {
        case 0:
        case 5:
            return kOuter[zm];
        case 2:
        case 3:
            return kInner[zm];
        default: {
            double xl = xs - xm, zl = zs - zm;
            if (((xm + zm) % 2) == 1) xl = 1.0 - xl;
            if (xl == 0.0) xl = 0.0001;
            return (zl / xl) < 1.0 ? kBelow[zm] : kAbove[zm];
        }
    }
}

double cubic(const Vec3& p) {
    const double x = p.x, y = p.y, z = p.z;
    const double ax = std::fabs(x), ay = std::fabs(y), az = std::fabs(z);
    if (x >= 0 && x >= ay && x >= az) return 0.0;
    if (y >= 0 && y >= ax && y >= az) return 1.0;
    if (z >= 0 && z >= ax && z >= ay) return 2.0;
    if (x < 0 && x <= -ay && x <= -az) return 3.0;
    if (y < 0 && y <= -ax && y <= -az) return 4.0;
    return 5.0;
}

double square(const Vec3& p) {
    int vx = pov_int(std::floor(p.x));
    int vz = pov_int(std::floor(p.z));
    if (vx & 1) return (vz & 1) ? 2.0 : 3.0;
    return (vz & 1) ? 1.0 : 0.0;
}

double triangular(const Vec3& p) {
    double xs = p.x - 3.0 * std::floor(p.x / 3.0);
    double zs = p.z - kSqrt3 * std::floor(p.z / kSqrt3);
    int a = pov_int(std::floor(xs));
    xs -= a;
    bool b = !(zs < kSqrt3Half);
    if (b) zs = kSqrt3 - zs;  // mirror the upper half
    double k = 1.0 - xs;
    double answer = 0.0;
    if (xs != 0.0 && k != 0.0) {
        int c = (zs / xs < kSqrt3 ? 1 : 0) + (zs / k < kSqrt3 ? 2 : 0);
        if (c == 3) {
            answer = 0.0;
        } else if (c == 2) {
            answer = 1.0;
        } else if (c == 1) {
            answer = 3.0;
        }
    } else {
        answer = 1.0;
    }
    int mask = static_cast<int>(answer);
    answer = (mask & 1) ? std::fmod(answer + 2.0 * a, 6.0) : std::fmod(6.0 + answer - 2.0 * a, 6.0);
    return b ? 5.0 - answer : answer;
}

double leopard(const Vec3& p) {
    double t1 = std::sin(p.x), t2 = std::sin(p.y), t3 = std::sin(p.z);
    double v = (t1 + t2 + t3) / 3.0;
    return v * v;
}

double marble(const PatternParams& params, const Vec3& p, int gen) {
    const Warp* turb = classic_turbulence(params);
    double turb_val =
        turb ? turb->turbulence.amount.x * turbulence(p, turb_params(turb->turbulence), gen) : 0.0;
    return p.x + turb_val;
}

double onion(const Vec3& p) { return std::fmod(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z), 1.0); }

double planar(const Vec3& p) { return clip_density(std::fabs(p.y)); }

// quilt_cubic: a Bezier blend with end values 0 and 1 and control values c0, c1.
double quilt_cubic(double t, double c0, double c1) {
    constexpr double kInvSqrt3Over4 = 1.154700538;
    double it = 1 - t;
    double itsqrd = it * it;
    double tsqrd = t * t;
    double tcubed = t * tsqrd;
    return (tcubed + 3.0 * t * itsqrd * c0 + 3.0 * tsqrd * it * c1) * kInvSqrt3Over4;
}

Vec3 quilt_vector(const PatternParams& params, const Vec3& p) {
    Vec3 v(p.x - pov_floor(p.x) - 0.5, p.y - pov_floor(p.y) - 0.5, p.z - pov_floor(p.z) - 0.5);
    double t = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    t = quilt_cubic(t, params.control0, params.control1);
    return {v.x * t, v.y * t, v.z * t};
}

double quilted(const PatternParams& params, const Vec3& p) {
    Vec3 v = quilt_vector(params, p);
    return (std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z)) / 3.0;
}

double radial(const Vec3& p) {
    if (std::fabs(p.x) < 0.001 && std::fabs(p.z) < 0.001) return 0.25;
    return 0.25 + (std::atan2(p.x, p.z) + kPi) / kTwoPi;
}

double ripples(const PatternParams& params, const Vec3& p, const PatternContext& ctx) {
    const WaveTables& w = wave_tables();
    const int n = wave_count(ctx);
    double scalar = 0.0;
    for (int i = 0; i < n; ++i) {
        double len = length(p - w.source[i]);
        if (len == 0.0) len = 1.0;
        scalar += cycloidal(len * params.frequency + params.phase);
    }
    return 0.5 * (1.0 + (scalar / static_cast<double>(n)));
}

double waves(const PatternParams& params, const Vec3& p, const PatternContext& ctx) {
    const WaveTables& w = wave_tables();
    const int n = wave_count(ctx);
    double scalar = 0.0;
    for (int i = 0; i < n; ++i) {
        double len = length(p - w.source[i]);
        if (len == 0.0) len = 1.0;
        double index = len * params.frequency * w.frequency[i] + params.phase;
        scalar += cycloidal(index) / w.frequency[i];
    }
    return 0.2 * (2.5 + (scalar / static_cast<double>(n)));
}

// Angle around the z axis in [0, 2 pi), as spiral1/spiral2 compute it.
double spiral_angle(double x, double y, double rad) {
    if (rad == 0.0) return 0.0;
    return x < 0.0 ? 3.0 * kHalfPi - std::asin(y / rad) : kHalfPi + std::asin(y / rad);
}

double spiral_turbulence(const PatternParams& params, const Vec3& p, int gen) {
    const Warp* turb = classic_turbulence(params);
    return turb ? turb->turbulence.amount.x * turbulence(p, turb_params(turb->turbulence), gen)
                : 0.0;
}

double spiral1(const PatternParams& params, const Vec3& p, int gen) {
    double turb_val = spiral_turbulence(params, p, gen);
    double rad = std::sqrt(p.x * p.x + p.y * p.y);
    double phi = spiral_angle(p.x, p.y, rad);
    return p.z + rad + static_cast<double>(params.arms) * phi / kTwoPi + turb_val;
}

double spiral2(const PatternParams& params, const Vec3& p, int gen) {
    double turb_val = spiral_turbulence(params, p, gen);
    double rad = std::sqrt(p.x * p.x + p.y * p.y);
    double phi = spiral_angle(p.x, p.y, rad);
    turb_val =
        triangle_wave(p.z + rad + static_cast<double>(params.arms) * phi / kTwoPi + turb_val);
    return triangle_wave(rad) + turb_val;
}

double spherical(const Vec3& p) { return clip_density(length(p)); }

double wood(const PatternParams& params, const Vec3& p) {
    double px = 0.0, py = 0.0;
    if (const Warp* turb = classic_turbulence(params)) {
        Vec3 t = dturbulence(p, turb_params(turb->turbulence));
        px = cycloidal((p.x + t.x) * turb->turbulence.amount.x);
        py = cycloidal((p.y + t.y) * turb->turbulence.amount.y);
    }
    px += p.x;
    py += p.y;
    return std::sqrt(px * px + py * py);
}

double wrinkles(const Vec3& p, int gen) {
    double value;
    if (gen > 1) {
        value = std::clamp(noise(p, gen) * 2.0 - 0.5, 0.0, 1.0);
    } else {
        value = noise(p, gen);
    }
    double lambda = 2.0, omega = 0.5;
    for (int i = 1; i < 10; ++i) {
        Vec3 q = p * lambda;
        if (gen > 1) {
            value += omega * std::clamp(noise(q, gen) * 2.0 - 0.5, 0.0, 1.0);
        } else {
            value += omega * noise(q, gen);
        }
        lambda *= 2.0;
        omega *= 0.5;
    }
    return value / 2.0;
}

// `function { pattern { ... } }` or `function { pigment { ... } }` called from a function
// (POV-Ray's f_pattern and f_pigment): the pattern's own transform, then the pattern value; a
// pigment is evaluated at the point as given, like a surface point with no uv.
void function_hook(const void* user, const scene::Function& f, const Vec3& p, double out[5]) {
    const PatternContext& ctx = *static_cast<const PatternContext*>(user);
    const scene::Pigment& pg = f.pigment.at(0);
    if (f.kind == scene::FunctionKind::Pattern) {
        out[0] = evaluate_pattern(pg.kind, pg.params, pg.transform.inverse_point(p), ctx);
        return;
    }
    scene::ColorFT c;
    PigmentEvaluator(ctx.textures, ctx).evaluate(pg, {p, {}, false}, &c);
    out[0] = c.rgb.r;
    out[1] = c.rgb.g;
    out[2] = c.rgb.b;
    out[3] = c.filter;
    out[4] = c.transmit;
}

// POV-Ray's function_pattern: the function at the point, values above 1 wrapped by fmod.
double function_pattern(const PatternParams& params, const Vec3& p, const PatternContext& ctx) {
    if (!ctx.functions || params.function < 0) return 0.0;
    const scene::FunctionEnv env = user_function_env(ctx);
    const double args[3] = {p.x, p.y, p.z};
    double v = scene::evaluate_function(env, params.function, args, 3);
    return v > 1.0 ? std::fmod(v, 1.0) : v;
}

double raw_pattern(PatternKind kind, const PatternParams& params, const Vec3& p,
                   const PatternContext& ctx) {
    switch (kind) {
        case PatternKind::Agate:
            return agate(params, p, noise_generator(params, ctx));
        case PatternKind::Bozo:
        case PatternKind::Spotted:
        case PatternKind::Bumps:
            return noise(p, noise_generator(params, ctx));
        case PatternKind::Boxed:
            return boxed(p);
        case PatternKind::Brick:
            return brick(params, p);
        case PatternKind::Cells:
            return cells(p);
        case PatternKind::Checker:
            return checker(p);
        case PatternKind::Crackle:
            return crackle(params, p, noise_generator(params, ctx));
        case PatternKind::Cylindrical:
            return cylindrical(p);
        case PatternKind::Dents: {
            double n = noise(p, noise_generator(params, ctx));
            return n * n * n;
        }
        case PatternKind::Gradient:
            return gradient(params, p);
        case PatternKind::Granite:
            return granite(p, noise_generator(params, ctx));
        case PatternKind::Hexagon:
            return hexagon(p);
        case PatternKind::Square:
            return square(p);
        case PatternKind::Triangular:
            return triangular(p);
        case PatternKind::Cubic:
            return cubic(p);
        case PatternKind::Object:
            return ctx.objects && params.object >= 0 && ctx.objects->inside(params.object, p)
                       ? 1.0
                       : 0.0;
        case PatternKind::Slope:
            return slope_pattern(params.slope, p, ctx);
        case PatternKind::Aoi:
            return aoi_pattern(ctx);
        case PatternKind::PigmentPattern:
            return pigment_pattern(params, p, ctx);
        case PatternKind::ImagePattern:
            return image_pattern(params, p, ctx);
        case PatternKind::Leopard:
            return leopard(p);
        case PatternKind::Mandel:
        case PatternKind::Julia: {
            const bool julia = kind == PatternKind::Julia;
            // POV-Ray's parser truncates the exponent and allows 2..33.
            const int e = std::clamp(static_cast<int>(params.fractal_exponent), 2,
                                     kMaxFractalExponent);
            if (e == 3 || e == 4) return fractal34(params, p, julia, e);
            if (e > 4) return fractalx(params, p, julia, e);
            return fractal2(params, p, julia);
        }
        case PatternKind::Magnet:
            return magnet(params, p);
        case PatternKind::Tiling:
            return tiling(params.tiling_type, p);
        case PatternKind::Marble:
            return marble(params, p, noise_generator(params, ctx));
        case PatternKind::Onion:
            return onion(p);
        case PatternKind::Planar:
            return planar(p);
        case PatternKind::Quilted:
            return quilted(params, p);
        case PatternKind::Radial:
            return radial(p);
        case PatternKind::Ripples:
            return ripples(params, p, ctx);
        case PatternKind::Spherical:
            return spherical(p);
        case PatternKind::Spiral1:
            return spiral1(params, p, noise_generator(params, ctx));
        case PatternKind::Spiral2:
            return spiral2(params, p, noise_generator(params, ctx));
        case PatternKind::Waves:
            return waves(params, p, ctx);
        case PatternKind::Wood:
            return wood(params, p);
        case PatternKind::Wrinkles:
            return wrinkles(p, noise_generator(params, ctx));
        case PatternKind::Function:
            return function_pattern(params, p, ctx);
        case PatternKind::DensityFile:
            return density_file(params, p);
        case PatternKind::Facets:  // normal-only; as a value POV-Ray has none
        case PatternKind::Plain:
        case PatternKind::ImageMap:
        case PatternKind::Average:
            return 0.0;
    }
    return 0.0;
}

// ---- Special normals (normal.cpp). `n` and the result are in the warped pattern space. ----

// PickInCube: the jittered point of the cube holding tv (floor of tv - EPSILON).
Vec3 pick_in_cube(const Vec3& tv) {
    Vec3 flo(std::floor(tv.x - kPovEpsilon), std::floor(tv.y - kPovEpsilon),
             std::floor(tv.z - kPovEpsilon));
    unsigned seed = static_cast<unsigned>(hash3d(pov_int(flo.x), pov_int(flo.y), pov_int(flo.z)));
    return {flo.x + pattern_random(seed), flo.y + pattern_random(seed + 1),
            flo.z + pattern_random(seed + 2)};
}

Vec3 facets_normal(const PatternParams& params, const Vec3& p, const Vec3& normal_in) {
    const double metric = params.facets_metric;
    Vec3 n = normalize(normal_in);
    const bool use_coords = params.facets_coords != 0.0;
    Vec3 tv = use_coords ? p : n;
    double scale = params.facets_size < 1e-6 ? 1e6 : 1. / params.facets_size;
    tv = tv * scale;
    auto distance = [metric](const Vec3& d) {
        if (metric == 2) return d.x * d.x + d.y * d.y + d.z * d.z;
        if (metric == 1) return d.x + d.y + d.z;  // sic: POV-Ray's facets sums signed values
        return std::pow(std::fabs(d.x), metric) + std::pow(std::fabs(d.y), metric) +
               std::pow(std::fabs(d.z), metric);
    };
    // POV-Ray walks the 5x5x5 block with double steps, knight-move cubes only.
    double best = 0.0;
    Vec3 nearest;
    bool first = true;
    for (double ax = -2.0; ax < 2.5; ax += 1.0)
        for (double ay = -2.0; ay < 2.5; ay += 1.0)
            for (double az = -2.0; az < 2.5; az += 1.0) {
                if ((std::fabs(ax) > 1.5) + (std::fabs(ay) > 1.5) + (std::fabs(az) > 1.5) > 1)
                    continue;
                Vec3 c = pick_in_cube(tv + Vec3(ax, ay, az));
                double s = distance(c - tv);
                if (first || s < best) {
                    best = s;
                    nearest = c;
                    first = false;
                }
            }
    if (use_coords) {
        Vec3 pert = dnoise(nearest);
        double s = dot(pert, n);
        pert = pert - n * s;
        return n + pert * params.facets_coords;
    }
    return nearest;
}

}  // namespace

scene::FunctionEnv user_function_env(const PatternContext& ctx) {
    scene::FunctionEnv env;
    env.functions = ctx.functions;
    env.noise_generator = ctx.noise_generator;
    env.pattern = &function_hook;
    env.user = &ctx;
    return env;
}

bool is_block_pattern(PatternKind kind) {
    switch (kind) {
        case PatternKind::Checker:
        case PatternKind::Brick:
        case PatternKind::Hexagon:
        case PatternKind::Square:
        case PatternKind::Triangular:
        case PatternKind::Cubic:
        case PatternKind::Object:
            return true;
        default:
            return false;
    }
}


double evaluate_pattern(PatternKind kind, const PatternParams& params, const Vec3& p,
                        const PatternContext& ctx) {
    const Vec3 q = warp_point(kind, params, p);
    double value = raw_pattern(kind, params, q, ctx);
    if (is_block_pattern(kind)) return value;
    // Evaluate_TPat: frequency and phase, with POV-Ray's 1.00001 modulus, then the wave.
    if (params.frequency != 0.0)
        value = std::fmod(value * params.frequency + params.phase, 1.00001);
    if (value < 0.0) value -= std::floor(value);
    switch (params.wave) {
        case scene::WaveType::Ramp:
            break;
        case scene::WaveType::Sine:
            value = (1.0 + cycloidal(value)) * 0.5;
            break;
        case scene::WaveType::Triangle:
            value = triangle_wave(value);
            break;
        case scene::WaveType::Scallop:
            value = std::fabs(cycloidal(value * 0.5));
            break;
        case scene::WaveType::Cubic:
            value = value * value * ((-2.0 * value) + 3.0);
            break;
        case scene::WaveType::Poly:
            value = std::pow(value, params.wave_exponent);
            break;
    }
    return value;
}

bool has_special_normal(PatternKind kind) {
    switch (kind) {
        case PatternKind::Bumps:
        case PatternKind::Dents:
        case PatternKind::Ripples:
        case PatternKind::Waves:
        case PatternKind::Wrinkles:
        case PatternKind::Quilted:
        case PatternKind::Facets:
            return true;
        default:
            return false;
    }
}

Vec3 special_normal(PatternKind kind, const PatternParams& params, const Vec3& p_pattern,
                    const Vec3& normal, double amount, const PatternContext& ctx) {
    // Warp_Normal: `warp { transform }` entries (and transforms written before another warp)
    // carry the normal into the warped space, where it is unit length again: the amount
    // below perturbs a unit normal whatever the transforms' scale.
    Vec3 n = normal;
    bool warped = false;
    for (const Warp& w : params.warps) {
        if (w.kind != WarpKind::Transform) continue;
        n = w.transform.inverse().normal(n);
        warped = true;
    }
    if (warped) {
        const double len = length(n);
        if (len > 0.0) n = n / len;
    }
    const Vec3 p = warp_point(kind, params, p_pattern);
    switch (kind) {
        case PatternKind::Bumps:
            n += dnoise(p) * amount;
            break;
        case PatternKind::Dents: {
            double v = noise(p, noise_generator(params, ctx));
            n += dnoise(p) * (v * v * v * amount);
            break;
        }
        case PatternKind::Ripples:
        case PatternKind::Waves: {
            const WaveTables& w = wave_tables();
            const int count = wave_count(ctx);
            const bool is_waves = kind == PatternKind::Waves;
            for (int i = 0; i < count; ++i) {
                Vec3 d = p - w.source[i];
                double len = length(d);
                if (len == 0.0) len = 1.0;
                double scalar;
                if (is_waves) {
                    double index = len * params.frequency * w.frequency[i] + params.phase;
                    scalar = cycloidal(index) * amount / w.frequency[i];
                } else {
                    scalar = cycloidal(len * params.frequency + params.phase) * amount;
                }
                n += d * (scalar / (len * static_cast<double>(count)));
            }
            break;
        }
        case PatternKind::Wrinkles: {
            Vec3 sum(0, 0, 0);
            double scale = 1.0;
            for (int i = 0; i < 10; scale *= 2.0, ++i) {
                Vec3 v = dnoise(p * scale);
                sum.x += std::fabs(v.x / scale);
                sum.y += std::fabs(v.y / scale);
                sum.z += std::fabs(v.z / scale);
            }
            n += sum * amount;
            break;
        }
        case PatternKind::Quilted:
            n += quilt_vector(params, p) * amount;
            break;
        case PatternKind::Facets:
            n = facets_normal(params, p, n);
            break;
        default:
            break;
    }
    // UnWarp_Normal: back through the warp transforms, last first.
    for (auto it = params.warps.rbegin(); it != params.warps.rend(); ++it)
        if (it->kind == WarpKind::Transform) n = it->transform.normal(n);
    double len = length(n);
    return len > 0.0 ? n / len : normal;
}

}  // namespace glint::render
