#include "render/focal_blur.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/noise.h"
#include "render/media/pov_media.h"

namespace glint::render {
namespace {

// POV-Ray's jitter values (backend/support/jitter.cpp, JitterTable): 256 offsets in
// [-0.5, 0.5], indexed through the noise hash table. Data, kept to the digit.
constexpr float kJitter[256] = {
    -0.500000f, 0.005890f,  0.011749f,  -0.490234f, 0.023468f,  -0.470703f, -0.480469f, 0.017609f,
    0.046906f,  -0.447266f, -0.441406f, 0.056671f,  -0.460938f, 0.044952f,  0.035187f,  -0.466797f,
    0.093781f,  -0.400391f, -0.394531f, 0.103546f,  -0.382813f, 0.123077f,  0.113312f,  -0.388672f,
    -0.421875f, 0.084015f,  0.089874f,  -0.412109f, 0.070343f,  -0.423828f, -0.433594f, 0.064484f,
    0.187531f,  -0.306641f, -0.300781f, 0.197296f,  -0.289063f, 0.216827f,  0.207062f,  -0.294922f,
    -0.265625f, 0.240265f,  0.246124f,  -0.255859f, 0.226593f,  -0.267578f, -0.277344f, 0.220734f,
    -0.343750f, 0.162140f,  0.167999f,  -0.333984f, 0.179718f,  -0.314453f, -0.324219f, 0.173859f,
    0.140656f,  -0.353516f, -0.347656f, 0.150421f,  -0.367188f, 0.138702f,  0.128937f,  -0.373047f,
    0.375031f,  -0.119141f, -0.113281f, 0.384796f,  -0.101563f, 0.404327f,  0.394562f,  -0.107422f,
    -0.078125f, 0.427765f,  0.433624f,  -0.068359f, 0.414093f,  -0.080078f, -0.089844f, 0.408234f,
    -0.031250f, 0.474640f,  0.480499f,  -0.021484f, 0.492218f,  -0.001953f, -0.011719f, 0.486359f,
    0.453156f,  -0.041016f, -0.035156f, 0.462921f,  -0.054688f, 0.451202f,  0.441437f,  -0.060547f,
    -0.187500f, 0.318390f,  0.324249f,  -0.177734f, 0.335968f,  -0.158203f, -0.167969f, 0.330109f,
    0.359406f,  -0.134766f, -0.128906f, 0.369171f,  -0.148438f, 0.357452f,  0.347687f,  -0.154297f,
    0.281281f,  -0.212891f, -0.207031f, 0.291046f,  -0.195313f, 0.310577f,  0.300812f,  -0.201172f,
    -0.234375f, 0.271515f,  0.277374f,  -0.224609f, 0.257843f,  -0.236328f, -0.246094f, 0.251984f,
    -0.249969f, 0.255859f,  0.261719f,  -0.240204f, 0.273438f,  -0.220673f, -0.230438f, 0.267578f,
    0.296875f,  -0.197235f, -0.191376f, 0.306641f,  -0.210907f, 0.294922f,  0.285156f,  -0.216766f,
    0.343750f,  -0.150360f, -0.144501f, 0.353516f,  -0.132782f, 0.373047f,  0.363281f,  -0.138641f,
    -0.171844f, 0.333984f,  0.339844f,  -0.162079f, 0.320313f,  -0.173798f, -0.183563f, 0.314453f,
    0.437500f,  -0.056610f, -0.050751f, 0.447266f,  -0.039032f, 0.466797f,  0.457031f,  -0.044891f,
    -0.015594f, 0.490234f,  0.496094f,  -0.005829f, 0.476563f,  -0.017548f, -0.027313f, 0.470703f,
    -0.093719f, 0.412109f,  0.417969f,  -0.083954f, 0.429688f,  -0.064423f, -0.074188f, 0.423828f,
    0.390625f,  -0.103485f, -0.097626f, 0.400391f,  -0.117157f, 0.388672f,  0.378906f,  -0.123016f,
    0.125000f,  -0.369110f, -0.363251f, 0.134766f,  -0.351532f, 0.154297f,  0.144531f,  -0.357391f,
    -0.328094f, 0.177734f,  0.183594f,  -0.318329f, 0.164063f,  -0.330048f, -0.339813f, 0.158203f,
    -0.281219f, 0.224609f,  0.230469f,  -0.271454f, 0.242188f,  -0.251923f, -0.261688f, 0.236328f,
    0.203125f,  -0.290985f, -0.285126f, 0.212891f,  -0.304657f, 0.201172f,  0.191406f,  -0.310516f,
    -0.437469f, 0.068359f,  0.074219f,  -0.427704f, 0.085938f,  -0.408173f, -0.417938f, 0.080078f,
    0.109375f,  -0.384735f, -0.378876f, 0.119141f,  -0.398407f, 0.107422f,  0.097656f,  -0.404266f,
    0.031250f,  -0.462860f, -0.457001f, 0.041016f,  -0.445282f, 0.060547f,  0.050781f,  -0.451141f,
    -0.484344f, 0.021484f,  0.027344f,  -0.474579f, 0.007813f,  -0.486298f, -0.496063f, 0.001953f,
};

// POV-Ray's Jitter2d(DBL x, DBL y, jx, jy) (jitter.h): two offsets in [-0.5, 0.5] for a
// position, from the hash of its coordinates scaled by the primes 1019 and 1021. The int
// conversions truncate towards zero as C's do.
void jitter2d(double x, double y, double* jx, double* jy) {
    auto pick = [](double a, double b, double ka, double kb) {
        const int i = noise_hash(static_cast<int>(a * ka) & 0xfff);
        const int j = noise_hash((i ^ static_cast<int>(b * kb)) & 0xfff);
        return static_cast<double>(kJitter[j & 0xff]);
    };
    *jx = pick(x, y, 1021.0, 1019.0);
    *jy = pick(x, y, 1019.0, 1021.0);
}

// The aperture's standard grids (tracepixel.cpp): four points, then hexagonal grids of 7, 19
// and 37 points, each with its jitter and its batch sizes. Data, kept to the digit.
constexpr Vec2 kSquare4[] = {{-0.25, 0.25}, {0.25, 0.25}, {-0.25, -0.25}, {0.25, -0.25}};
constexpr Vec2 kHex7[] = {{-0.288675, 0.0},   {0.0, 0.0},       {0.288675, 0.0},  {-0.144338, 0.25},
                          {-0.144338, -0.25}, {0.144338, 0.25}, {0.144338, -0.25}};
constexpr Vec2 kHex19[] = {{-0.192450, 0.333333},
                           {-0.192450, -0.333333},
                           {0.192450, 0.333333},
                           {0.192450, -0.333333},
                           {0.384900, 0.0},
                           {-0.384900, 0.0},
                           {0.0, 0.0},
                           {0.0, 0.333333},
                           {0.0, -0.333333},
                           {-0.288675, 0.166667},
                           {-0.288675, -0.166667},
                           {0.288675, 0.166667},
                           {0.288675, -0.166667},
                           {-0.096225, 0.166667},
                           {-0.096225, -0.166667},
                           {0.096225, 0.166667},
                           {0.096225, -0.166667},
                           {-0.192450, 0.0},
                           {0.192450, 0.0}};
constexpr Vec2 kHex37[] = {
    {0.0, 0.0},          {-0.216506, 0.375}, {0.216506, -0.375}, {-0.216506, -0.375},
    {0.216506, 0.375},   {-0.433013, 0.0},   {0.433013, 0.0},    {-0.144338, 0.25},
    {0.144338, -0.25},   {-0.144338, -0.25}, {0.144338, 0.25},   {-0.288675, 0.0},
    {0.288675, 0.0},     {-0.072169, 0.125}, {0.072169, -0.125}, {-0.072169, -0.125},
    {0.072169, 0.125},   {-0.144338, 0.0},   {0.144338, 0.0},    {-0.360844, 0.125},
    {-0.360844, -0.125}, {0.360844, 0.125},  {0.360844, -0.125}, {-0.288675, 0.25},
    {-0.288675, -0.25},  {0.288675, 0.25},   {0.288675, -0.25},  {-0.072169, 0.375},
    {-0.072169, -0.375}, {0.072169, 0.375},  {0.072169, -0.375}, {-0.216506, 0.125},
    {-0.216506, -0.125}, {0.216506, 0.125},  {0.216506, -0.125}, {0.0, 0.25},
    {0.0, -0.25}};
constexpr double kHexJitter7 = 0.144338, kHexJitter19 = 0.096225, kHexJitter37 = 0.0721688;
constexpr int kBatches7[] = {7, 0};
constexpr int kBatches19[] = {7, 6, 6, 0};
constexpr int kBatches37[] = {7, 6, 6, 4, 4, 4, 4, 2, 0};

// POV-Ray's sub-random points on a disc of radius `radius` (randomsequences.cpp,
// HaltonOnDiscGenerator with bases 2 and 3): point i takes the radius squared from the base-2
// radical inverse of i + 1 and the angle from the base-3 one.
double radical_inverse(unsigned base, size_t i) {
    double h = 0, q = 1.0 / base;
    for (; i > 0; i /= base, q /= base) h += static_cast<double>(i % base) * q;
    return h;
}
Vec2 halton_disc(size_t i, double radius) {
    const double r = std::sqrt(0.0 + radical_inverse(2, i + 1) * (radius * radius));
    const double theta = 0.0 + radical_inverse(3, i + 1) * (2 * kPi);
    return {r * std::cos(theta), r * std::sin(theta)};
}

// The standard grid for `n` rays and the rest spread over the disc's free cells of an odd
// grid, as FocalBlurData places them (without a bokeh pigment).
std::vector<Vec2> aperture_grid(int n, const int** batches, double* max_jitter) {
    const Vec2* standard = kSquare4;
    int standard_size = 4;
    *batches = nullptr;
    if (n >= 37) {
        standard = kHex37, standard_size = 37, *batches = kBatches37;
    } else if (n >= 19) {
        standard = kHex19, standard_size = 19, *batches = kBatches19;
    } else if (n >= 7) {
        standard = kHex7, standard_size = 7, *batches = kBatches7;
    }
    switch (n) {
        case 7:
            *max_jitter = kHexJitter7;
            break;
        case 19:
            *max_jitter = kHexJitter19;
            break;
        case 37:
            *max_jitter = kHexJitter37;
            break;
        default:
            *max_jitter = 0.5 / std::sqrt(static_cast<double>(n));
            break;
    }
    std::vector<Vec2> grid(standard, standard + std::min(standard_size, n));
    if (n <= standard_size) return grid;
    const int cells = 2 * static_cast<int>(std::ceil(std::sqrt(n / kPi))) + 1;
    std::vector<unsigned char> taken(static_cast<size_t>(cells) * cells, 0);
    auto cell = [&](const Vec2& v) {
        const int xi = std::min(static_cast<int>((v.x + 0.5) * cells), cells - 1);
        const int yi = std::min(static_cast<int>((v.y + 0.5) * cells), cells - 1);
        return static_cast<size_t>(yi) * cells + xi;
    };
    for (const Vec2& v : grid) ++taken[cell(v)];
    // Draws stop being choosy once only as many are left as rays to place.
    size_t remain = static_cast<size_t>(n) * 10, drawn = 0;
    for (int i = standard_size; i < n; ++i) {
        Vec2 v = halton_disc(drawn++, 0.5);
        --remain;
        while ((taken[cell(v)] || v.x * v.x + v.y * v.y > 0.25) &&
               remain > static_cast<size_t>(n - i)) {
            v = halton_disc(drawn++, 0.5);
            --remain;
        }
        grid.push_back(v);
        ++taken[cell(v)];
    }
    return grid;
}

}  // namespace

FocalBlur::FocalBlur(const Camera& camera) : camera_(camera), ir_(camera.ir()) {
    const scene::Camera& ir = ir_;
    const scene::FocalBlur& fb = ir.focal_blur;
    if (!fb.active() || fb.samples > 1000000)
        throw Error(ErrorKind::Render, ir.loc,
                    "focal blur needs an aperture and 1 to 1000000 samples");
    const int n = fb.samples;
    thresholds_.assign(n, 0.0);
    if (n > 1) {
        const double t1 = fb.variance / PovMedia::chi_square_upper_inverse(n - 1, fb.confidence);
        for (int i = 0; i < n; ++i)
            thresholds_[i] = t1 * PovMedia::chi_square_upper_inverse(i + 1, fb.confidence);
    }
    grid_ = aperture_grid(n, &batches_, &max_jitter_);
    x_perp_ = normalize(cross(ir.up, ir.direction));
    y_perp_ = normalize(cross(ir.direction, x_perp_));
    focal_scale_ = fb.focal_distance / length(ir.direction);
}

std::optional<Ray> FocalBlur::ray(double x, double y, int number) const {
    std::optional<Ray> r = camera_.generate(x, y);
    if (!r) return r;
    // The pinhole direction at POV-Ray's length: the perspective one unnormalized.
    Vec3 d = r->dir;
    if (ir_.kind == scene::CameraKind::Perspective) {
        double sx, sy;
        camera_.screen(x, y, &sx, &sy);
        d = ir_.direction + ir_.right * sx + ir_.up * sy;
    }
    // JitterCameraRay sees the position after CreateCameraRay's move to the pixel centre.
    double jx, jy;
    jitter2d(x + 0.5, y - 0.5, &jx, &jy);
    const double radius = ir_.focal_blur.aperture * 0.5;
    const Vec2& g = grid_[number];
    const double xlen = radius * (g.x + jx * max_jitter_ * 2.0);
    const double ylen = radius * (g.y + jy * max_jitter_ * 2.0);
    const Vec3 deflection = x_perp_ * xlen - y_perp_ * ylen;
    // The eye moves on the aperture and the ray turns back so that both meet where the
    // pinhole ray crosses the focal plane.
    r->origin = ir_.location + deflection;
    r->dir = normalize(d * focal_scale_ - deflection);
    return r;
}

Color FocalBlur::pixel(double x, double y, const std::function<Color(const Ray&)>& trace,
                       int* rays) const {
    constexpr int kSubPixels = 16;  // the sub-pixel grid rays are jittered within
    const scene::FocalBlur& fb = ir_.focal_blur;
    const int seed = static_cast<int>(x * 313.0 + 11.0) + static_cast<int>(y * 311.0 + 17.0);
    Color sum;
    // POV-Ray keeps colours as floats; the stopping test sees their sums as it does.
    float s1[3] = {0, 0, 0}, s2[3] = {0, 0, 0};
    int nr = 0, level = 0;
    do {
        int batch = 4;
        if (batches_ && batches_[level] > 0) batch = batches_[level++];
        for (int i = 0; i < batch && nr < fb.samples; ++i, ++nr) {
            const int dxi = noise_hash(seed + nr) % kSubPixels;
            const int dyi = noise_hash(seed + nr + 1) % kSubPixels;
            double dx = static_cast<double>(2 * dxi + 1) / (2 * kSubPixels) - 0.5;
            double dy = static_cast<double>(2 * dyi + 1) / (2 * kSubPixels) - 0.5;
            double jx, jy;
            jitter2d(dx, dy, &jx, &jy);
            dx += (jx - 0.5) / kSubPixels;
            dy += (jy - 0.5) / kSubPixels;
            Color c;
            if (std::optional<Ray> r = ray(x + dx, y + dy, nr)) c = trace(*r);
            sum += c;
            const float v[3] = {static_cast<float>(c.r), static_cast<float>(c.g),
                                static_cast<float>(c.b)};
            for (int k = 0; k < 3; ++k) {
                s1[k] += v[k];
                s2[k] += v[k] * v[k];
            }
        }
        const float n = static_cast<float>(nr);
        bool settled = nr >= fb.samples_min;
        for (int k = 0; k < 3 && settled; ++k) {
            const float var = (s2[k] / n - (s1[k] / n) * (s1[k] / n)) / n;
            settled = var < thresholds_[nr - 1];
        }
        if (settled) break;
    } while (nr < fb.samples);
    if (rays) *rays = nr;
    return sum * (1.0 / nr);
}

}  // namespace glint::render
