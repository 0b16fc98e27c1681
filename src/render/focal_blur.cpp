#include "render/focal_blur.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/noise.h"
#include "render/media/pov_media.h"
#include "render/pov_jitter.h"

namespace glint::render {
namespace {

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
    pov_jitter2d(x + 0.5, y - 0.5, &jx, &jy);
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
            pov_jitter2d(dx, dy, &jx, &jy);
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
