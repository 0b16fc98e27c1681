#include "core/noise.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>

namespace glint {
namespace {

// POV-Ray's RTable values (texture.cpp), 267 pseudo-random numbers in [-1, 1]. POV-Ray stores
// them interleaved with their halves (RTable[2i] = v_i, RTable[2i + 1] = v_i / 2) and indexes
// that array with even offsets; NoiseTables::rtable keeps the same layout so the indexing below
// reads like the original arithmetic.
constexpr double kRValues[267] = {
    -1,        0.604974,  -0.937102,  0.414115,  0.576226,   -0.0161593, 0.432334,    0.103685,
    0.590539,  0.0286412, 0.46981,    -0.84622,  -0.0734112, -0.304097,  -0.40206,    -0.210132,
    -0.919127, 0.652033,  -0.83151,   -0.183948, -0.671107,  0.852476,   0.043595,    -0.404532,
    0.75494,   -0.335653, 0.618433,   0.605707,  0.708583,   -0.477195,  0.899474,    0.490623,
    0.221729,  -0.400381, -0.853727,  -0.932586, 0.659113,   0.961303,   0.325948,    -0.750851,
    0.842466,  0.734401,  -0.649866,  0.394491,  -0.466056,  -0.434073,  0.109026,    0.0847028,
    -0.738857, 0.241505,  0.16228,    -0.71426,  -0.883665,  -0.150408,  -0.90396,    -0.686549,
    -0.785214, 0.488548,  0.0246433,  0.142473,  -0.602136,  0.375845,   -0.00779736, 0.498955,
    -0.268147, 0.856382,  -0.386007,  -0.596094, -0.867735,  -0.570977,  -0.914366,   0.28896,
    0.672206,  -0.233783, 0.94815,    0.895262,  0.343252,   -0.173388,  -0.767971,   -0.314748,
    0.824308,  -0.342092, 0.721431,   -0.24004,  -0.63653,   0.553277,   0.376272,    0.158984,
    -0.452659, 0.396323,  -0.420676,  -0.454154, 0.122179,   0.295857,   0.0664225,   -0.202075,
    -0.724788, 0.453513,  0.224567,   -0.908812, 0.176349,   -0.320516,  -0.697139,   0.742702,
    -0.900786, 0.471489,  -0.133532,  0.119127,  -0.889769,  -0.23183,   -0.669673,   -0.046891,
    -0.803433, -0.966735, 0.475578,   -0.652644, 0.0112459,  -0.730007,  0.128283,    0.145647,
    -0.619318, 0.272023,  0.392966,   0.646418,  -0.0207675, -0.315908,  0.480797,    0.535668,
    -0.250172, -0.83093,  -0.653773,  -0.443809, 0.119982,   -0.897642,  0.89453,     0.165789,
    0.633875,  -0.886839, 0.930877,   -0.537194, 0.587732,   0.722011,   -0.209461,   -0.0424659,
    -0.814267, -0.919432, 0.280262,   -0.66302,  -0.558099,  -0.537469,  -0.598779,   0.929656,
    -0.170794, -0.537163, 0.312581,   0.959442,  0.722652,   0.499931,   0.175616,    -0.534874,
    -0.685115, 0.444999,  0.17171,    0.108202,  -0.768704,  -0.463828,  0.254231,    0.546014,
    0.869474,  0.875212,  -0.944427,  0.130724,  -0.110185,  0.312184,   -0.33138,    -0.629206,
    0.0606546, 0.722866,  -0.0979477, 0.821561,  0.0931258,  -0.972808,  0.0318151,   -0.867033,
    -0.387228, 0.280995,  -0.218189,  -0.539178, -0.427359,  -0.602075,  0.311971,    0.277974,
    0.773159,  0.592493,  -0.0331884, -0.630854, -0.269947,  0.339132,   0.581079,    0.209461,
    -0.317433, -0.284993, 0.181323,   0.341634,  0.804959,   -0.229572,  -0.758907,   -0.336721,
    0.605463,  -0.991272, -0.0188754, -0.300191, 0.368307,   -0.176135,  -0.3832,     -0.749569,
    0.62356,   -0.573938, 0.278309,   -0.971313, 0.839994,   -0.830686,  0.439078,    0.66128,
    0.694514,  0.0565042, 0.54342,    -0.438804, -0.0228428, -0.687068,  0.857267,    0.301991,
    -0.494255, -0.941039, 0.775509,   0.410575,  -0.362081,  -0.671534,  -0.348379,   0.932433,
    0.886442,  0.868681,  -0.225666,  -0.062211, -0.0976425, -0.641444,  -0.848112,   0.724697,
    0.473503,  0.998749,  0.174701,   0.559625,  -0.029099,  -0.337392,  -0.958129,   -0.659785,
    0.236042,  -0.246937, 0.659449,   -0.027512, 0.821897,   -0.226215,  0.0181735,   0.500481,
    -0.420127, -0.427878, 0.566186};

// POV-Ray's lattice offset (MINX/MINY/MINZ), which keeps lattice indices positive.
constexpr int kLatticeMin = -10000;
// SolidNoise (noise_generator 3): table size and the offset that keeps coordinates positive.
constexpr int kSolidEntries = 2048;
constexpr double kSolidRollover = 10000000.023157213;

// POV-Ray's table generator: a 32-bit linear congruential step; the 15 bits used are
// (state >> 16) & 0x7FFF.
struct PovRand {
    int32_t state;
    int next15() {
        state = static_cast<int32_t>(static_cast<uint32_t>(state) * 1812433253u + 12345u);
        return (state >> 16) & 0x7FFF;
    }
};

struct NoiseTables {
    std::array<double, 267 * 2> rtable{};
    std::array<uint16_t, 8192> hash{};
    std::array<int, 2 * (kSolidEntries + 1)> perm{};
    std::array<Vec3, 2 * (kSolidEntries + 1)> gradient{};

    NoiseTables() {
        for (int i = 0; i < 267; ++i) {
            rtable[2 * i] = kRValues[i];
            rtable[2 * i + 1] = kRValues[i] * 0.5;
        }
        // InitTextureTable: a shuffled identity permutation of 0..4095, stored twice.
        for (int i = 0; i < 4096; ++i) hash[i] = static_cast<uint16_t>(i);
        PovRand r{0};
        for (int i = 4095; i >= 0; --i) {
            int j = r.next15() % 4096;
            std::swap(hash[i], hash[j]);
        }
        for (int i = 0; i < 4096; ++i) hash[4096 + i] = hash[i];

        // InitSolidNoise: unit gradients by rejection sampling, then a permutation.
        PovRand s{1};
        for (int i = 0; i < kSolidEntries; ++i) {
            Vec3 v;
            double len2;
            do {
                for (int k = 0; k < 3; ++k) {
                    v[k] =
                        static_cast<double>((s.next15() % (kSolidEntries << 1)) - kSolidEntries) /
                        static_cast<double>(kSolidEntries);
                }
                len2 = v.x * v.x + v.y * v.y + v.z * v.z;
            } while (len2 > 1.0 || len2 < 1.0e-5);
            double inv = 1.0 / std::sqrt(len2);
            gradient[i] = v * inv;
        }
        for (int i = 0; i < kSolidEntries; ++i) perm[i] = i;
        // POV-Ray's loop starts at index NoiseEntries (one past the identity it just wrote,
        // so the swap there reads a zero) and steps by two; kept for identical tables.
        for (int i = kSolidEntries; i > 0; i -= 2) {
            int k = perm[i];
            int j = s.next15() % kSolidEntries;
            perm[i] = perm[j];
            perm[j] = k;
        }
        for (int i = 0; i < kSolidEntries + 2; ++i) {
            perm[kSolidEntries + i] = perm[i];
            gradient[kSolidEntries + i] = gradient[i];
        }
    }
};

const NoiseTables& tables() {
    static const NoiseTables kTables;
    return kTables;
}

// x86's conversion of an out-of-range double to int gives INT_MIN; POV-Ray's (int) casts rely
// on it for huge coordinates. Spelled out so the behaviour is defined here.
inline int to_int(double v) {
    if (!(v > -2147483649.0 && v < 2147483648.0)) return INT32_MIN;
    return static_cast<int>(v);
}

// POV-Ray's "JB fix" lattice cell: truncation toward zero for x >= 0, and for x < 0 a
// truncation of x - (1 - EPSILON) (so tiny negatives land in cell 0, as in POV-Ray).
struct LatticeAxis {
    int index;    // cell index masked to 0..4095
    double frac;  // x - cell
};
inline LatticeAxis lattice(double x) {
    int cell = x >= 0 ? to_int(x) : to_int(x - (1 - kPovEpsilon));
    return {static_cast<int>((static_cast<unsigned>(cell) - static_cast<unsigned>(kLatticeMin)) &
                             0xFFFu),
            x - cell};
}

inline double scurve(double a) { return a * a * (3.0 - 2.0 * a); }

// The lattice noise's corner weights and hashes, shared by noise() and dnoise().
struct Lattice {
    double x_ix, y_iy, z_iz, x_jx, y_jy, z_jz;
    double sx, sy, sz, tx, ty, tz;
    int iz;
    int h00, h10, h01, h11;  // Hash2d of (ix, iy), (ix+1, iy), (ix, iy+1), (ix+1, iy+1)
};

inline Lattice make_lattice(const Vec3& p, const uint16_t* hash) {
    Lattice l;
    LatticeAxis ax = lattice(p.x), ay = lattice(p.y), az = lattice(p.z);
    l.x_ix = ax.frac;
    l.y_iy = ay.frac;
    l.z_iz = az.frac;
    l.iz = az.index;
    l.x_jx = l.x_ix - 1;
    l.y_jy = l.y_iy - 1;
    l.z_jz = l.z_iz - 1;
    l.sx = scurve(l.x_ix);
    l.sy = scurve(l.y_iy);
    l.sz = scurve(l.z_iz);
    l.tx = 1 - l.sx;
    l.ty = 1 - l.sy;
    l.tz = 1 - l.sz;
    auto hash2 = [hash](int a, int b) { return static_cast<int>(hash[hash[a] ^ b]); };
    l.h00 = hash2(ax.index, ay.index);
    l.h10 = hash2(ax.index + 1, ay.index);
    l.h01 = hash2(ax.index, ay.index + 1);
    l.h11 = hash2(ax.index + 1, ay.index + 1);
    return l;
}

// POV-Ray's Hash1dRTableIndex: an even offset into the interleaved RTable.
inline const double* rtable_at(const NoiseTables& t, int h, int iz) {
    return &t.rtable[(t.hash[h ^ iz] & 0xFF) * 2];
}

// POV-Ray's INCRSUMP: one corner's contribution.
inline double corner(const double* mp, double s, double x, double y, double z) {
    return s * (mp[1] + mp[2] * x + mp[4] * y + mp[6] * z);
}

double solid_noise(const Vec3& p) {
    const NoiseTables& t = tables();
    int b0[3], b1[3];
    double r0[3], r1[3];
    for (int k = 0; k < 3; ++k) {
        double v = p[k] + kSolidRollover;
        int it = to_int(std::floor(v));
        b0[k] = it & (kSolidEntries - 1);
        b1[k] = (b0[k] + 1) & (kSolidEntries - 1);
        r0[k] = v - it;
        r1[k] = r0[k] - 1.0;
    }
    int i = t.perm[b0[0]];
    int j = t.perm[b1[0]];
    int b00 = t.perm[i + b0[1]];
    int b10 = t.perm[j + b0[1]];
    int b01 = t.perm[i + b1[1]];
    int b11 = t.perm[j + b1[1]];
    double sx = scurve(r0[0]), sy = scurve(r0[1]), sz = scurve(r0[2]);
    auto at = [&t](int g, double rx, double ry, double rz) {
        const Vec3& q = t.gradient[g];
        return rx * q.x + ry * q.y + rz * q.z;
    };
    auto lerp = [](double f, double a, double b) { return a + f * (b - a); };
    double a = lerp(sx, at(b00 + b0[2], r0[0], r0[1], r0[2]), at(b10 + b0[2], r1[0], r0[1], r0[2]));
    double b = lerp(sx, at(b01 + b0[2], r0[0], r1[1], r0[2]), at(b11 + b0[2], r1[0], r1[1], r0[2]));
    double c = lerp(sy, a, b);
    a = lerp(sx, at(b00 + b1[2], r0[0], r0[1], r1[2]), at(b10 + b1[2], r1[0], r0[1], r1[2]));
    b = lerp(sx, at(b01 + b1[2], r0[0], r1[1], r1[2]), at(b11 + b1[2], r1[0], r1[1], r1[2]));
    double d = lerp(sy, a, b);
    return lerp(sz, c, d);
}

}  // namespace

double noise(const Vec3& p, int generator) {
    if (generator == 3) {
        // POV-Ray's correction of the gradient noise's bias towards [0, 1].
        double sum = 0.5 * (1.59 * solid_noise(p) + 0.985);
        return std::clamp(sum, 0.0, 1.0);
    }
    const NoiseTables& t = tables();
    const Lattice l = make_lattice(p, t.hash.data());
    const double txty = l.tx * l.ty, sxty = l.sx * l.ty, txsy = l.tx * l.sy, sxsy = l.sx * l.sy;
    double sum = corner(rtable_at(t, l.h00, l.iz), txty * l.tz, l.x_ix, l.y_iy, l.z_iz);
    sum += corner(rtable_at(t, l.h10, l.iz), sxty * l.tz, l.x_jx, l.y_iy, l.z_iz);
    sum += corner(rtable_at(t, l.h01, l.iz), txsy * l.tz, l.x_ix, l.y_jy, l.z_iz);
    sum += corner(rtable_at(t, l.h11, l.iz), sxsy * l.tz, l.x_jx, l.y_jy, l.z_iz);
    sum += corner(rtable_at(t, l.h00, l.iz + 1), txty * l.sz, l.x_ix, l.y_iy, l.z_jz);
    sum += corner(rtable_at(t, l.h10, l.iz + 1), sxty * l.sz, l.x_jx, l.y_iy, l.z_jz);
    sum += corner(rtable_at(t, l.h01, l.iz + 1), txsy * l.sz, l.x_ix, l.y_jy, l.z_jz);
    sum += corner(rtable_at(t, l.h11, l.iz + 1), sxsy * l.sz, l.x_jx, l.y_jy, l.z_jz);
    if (generator == 2) {
        // POV-Ray measured the raw range as [-1.05242, 0.988997] and stretches it to [0, 1].
        sum += 1.05242;
        sum *= 0.48985582;
    } else {
        sum = sum + 0.5;
    }
    return std::clamp(sum, 0.0, 1.0);
}

Vec3 dnoise(const Vec3& p) {
    const NoiseTables& t = tables();
    const Lattice l = make_lattice(p, t.hash.data());
    const double txty = l.tx * l.ty, sxty = l.sx * l.ty, txsy = l.tx * l.sy, sxsy = l.sx * l.sy;
    Vec3 r(0, 0, 0);
    // Each corner reads three consecutive 8-double windows of RTable, one per component;
    // POV-Ray visits the corners in this order (it differs from Noise's).
    auto add = [&](int h, int iz, double s, double x, double y, double z) {
        const double* mp = rtable_at(t, h, iz);
        double cx = corner(mp, s, x, y, z);
        double cy = corner(mp + 8, s, x, y, z);
        double cz = corner(mp + 16, s, x, y, z);
        r.x += cx;
        r.y += cy;
        r.z += cz;
    };
    add(l.h00, l.iz, txty * l.tz, l.x_ix, l.y_iy, l.z_iz);
    add(l.h10, l.iz, sxty * l.tz, l.x_jx, l.y_iy, l.z_iz);
    add(l.h11, l.iz, sxsy * l.tz, l.x_jx, l.y_jy, l.z_iz);
    add(l.h01, l.iz, txsy * l.tz, l.x_ix, l.y_jy, l.z_iz);
    add(l.h01, l.iz + 1, txsy * l.sz, l.x_ix, l.y_jy, l.z_jz);
    add(l.h11, l.iz + 1, sxsy * l.sz, l.x_jx, l.y_jy, l.z_jz);
    add(l.h10, l.iz + 1, sxty * l.sz, l.x_jx, l.y_iy, l.z_jz);
    add(l.h00, l.iz + 1, txty * l.sz, l.x_ix, l.y_iy, l.z_jz);
    return r;
}

double turbulence(const Vec3& p, const TurbulenceParams& turb, int generator) {
    // Generators 2 and 3 spread each octave to 2 * noise - 0.5; only the first is clamped.
    const bool spread = generator > 1;
    double value;
    if (spread) {
        value = std::clamp(2.0 * noise(p, generator) - 0.5, 0.0, 1.0);
    } else {
        value = noise(p, generator);
    }
    double l = turb.lambda, o = turb.omega;
    for (int i = 2; i <= turb.octaves; ++i) {
        Vec3 q = p * l;
        if (spread) {
            value += o * (2.0 * noise(q, generator) - 0.5);
        } else {
            value += o * noise(q, generator);
        }
        if (i < turb.octaves) {
            l *= turb.lambda;
            o *= turb.omega;
        }
    }
    return value;
}

int hash3d(int a, int b, int c) {
    const uint16_t* h = tables().hash.data();
    return h[h[h[a & 0xfff] ^ (b & 0xfff)] ^ (c & 0xfff)];
}

int noise_hash(int i) { return tables().hash[i & 0xfff]; }

double pattern_random(unsigned seed) {
    // boost::uniform_real<double>(0, 1) over mt19937 divides each 32-bit draw by 2^32;
    // std::mt19937's default seed is the same 5489. Only the first 4098 values can be reached
    // through hash3d (+2), so only those are stored; others are drawn on the fly.
    constexpr unsigned kStored = 4100;
    static const std::array<double, kStored> kValues = [] {
        std::array<double, kStored> v{};
        std::mt19937 gen;
        for (double& x : v) x = static_cast<double>(gen()) / 4294967296.0;
        return v;
    }();
    seed %= 32768u;
    if (seed < kStored) return kValues[seed];
    std::mt19937 gen;
    gen.discard(seed);
    return static_cast<double>(gen()) / 4294967296.0;
}

Vec3 dturbulence(const Vec3& p, const TurbulenceParams& turb) {
    Vec3 result = dnoise(p);
    double l = turb.lambda, o = turb.omega;
    for (int i = 2; i <= turb.octaves; ++i) {
        Vec3 v = dnoise(p * l);
        result.x += o * v.x;
        result.y += o * v.y;
        result.z += o * v.z;
        if (i < turb.octaves) {
            l *= turb.lambda;
            o *= turb.omega;
        }
    }
    return result;
}

}  // namespace glint
