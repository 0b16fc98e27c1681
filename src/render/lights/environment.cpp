#include "render/lights/environment.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "render/textures/image_texture.h"

namespace glint::render {
namespace {

// Rec. 709 luminance; negative and non-finite radiance count as none.
double luminance(const Color& c) {
    const double y = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    return std::isfinite(y) && y > 0 ? y : 0.0;
}

// Relative weight of the floor every cell gets on top of its radiance (see the header).
constexpr double kFloor = 1e-3;

void largest_image(const scene::Pigment& p, const TextureCache* textures, int* width) {
    if (p.kind == scene::PatternKind::ImageMap && textures) {
        if (const ImageTexture* t = textures->find(p.params.image))
            *width = std::max(*width, t->width());
    }
    for (const scene::Pigment& e : p.entries) largest_image(e, textures, width);
    for (const scene::PigmentMapEntry& e : p.pigment_map) largest_image(e.pigment[0], textures, width);
}

}  // namespace

Vec3 EnvironmentDistribution::direction(double u, double v) {
    const double phi = 2 * kPi * u, theta = kPi * v;
    const double st = std::sin(theta);
    return Vec3(st * std::cos(phi), std::cos(theta), st * std::sin(phi));
}

void EnvironmentDistribution::coordinates(const Vec3& d, double* u, double* v) {
    double phi = std::atan2(d.z, d.x);
    if (phi < 0) phi += 2 * kPi;
    *u = std::min(phi / (2 * kPi), kOneMinusEpsilon);
    *v = std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi;
}

EnvironmentDistribution::EnvironmentDistribution(const Radiance& radiance,
                                                 const EnvironmentGrid& grid)
    : width_(std::max(1, grid.width)), height_(std::max(1, grid.height)) {
    const int w = width_, h = height_, k = std::max(1, grid.subsamples);
    std::vector<double> peak(static_cast<size_t>(w) * h);
    // Rows are independent: the table is the same whatever the thread count.
    tbb::parallel_for(0, h, [&](int i) {
        for (int j = 0; j < w; ++j) {
            double m = 0;
            for (int a = 0; a < k; ++a)
                for (int b = 0; b < k; ++b) {
                    const double u = (j + (a + 0.5) / k) / w, v = (i + (b + 0.5) / k) / h;
                    m = std::max(m, luminance(radiance(direction(u, v))));
                }
            peak[static_cast<size_t>(i) * w + j] = m;
        }
    });
    std::vector<double> sin_theta(h);
    double sum = 0, weight = 0;
    for (int i = 0; i < h; ++i) {
        sin_theta[i] = std::sin(kPi * (i + 0.5) / h);
        for (int j = 0; j < w; ++j) sum += peak[static_cast<size_t>(i) * w + j] * sin_theta[i];
        weight += w * sin_theta[i];
    }
    const double mean = sum / weight;
    const double floor = std::isfinite(mean) && mean > 0 ? kFloor * mean : 1.0;
    std::vector<double> row_integral(h);
    rows_.reserve(h);
    for (int i = 0; i < h; ++i) {
        std::vector<double> f(w);
        for (int j = 0; j < w; ++j)
            f[j] = (peak[static_cast<size_t>(i) * w + j] + floor) * sin_theta[i];
        rows_.emplace_back(std::move(f));
        row_integral[i] = rows_.back().integral();
    }
    marginal_.emplace(std::move(row_integral));
}

bool EnvironmentDistribution::sample(Sample2 u, Vec3* dir, double* pdf) const {
    int i, j;
    double pv, pu;
    const double v = marginal_->sample(u.u, &i, &pv);
    const double uu = rows_[i].sample(u.v, &j, &pu);
    const double st = std::sin(kPi * v);
    if (!(st > 0)) return false;
    *dir = direction(uu, v);
    *pdf = pv * pu / (2 * kPi * kPi * st);
    return std::isfinite(*pdf) && *pdf > 0;
}

double EnvironmentDistribution::pdf(const Vec3& dir) const {
    double u, v;
    coordinates(dir, &u, &v);
    const double st = std::sqrt(std::max(0.0, 1 - dir.y * dir.y));
    if (!(st > 0)) return 0;
    const int i = std::clamp(static_cast<int>(v * height_), 0, height_ - 1);
    const int j = std::clamp(static_cast<int>(u * width_), 0, width_ - 1);
    return marginal_->pdf(i) * rows_[i].pdf(j) / (2 * kPi * kPi * st);
}

EnvironmentGrid environment_grid(const scene::Scene& scene, const TextureCache* textures) {
    EnvironmentGrid g;
    int image = 0;
    if (scene.sky_sphere)
        for (const scene::Pigment& p : scene.sky_sphere->pigments) largest_image(p, textures, &image);
    if (image > 0) {
        g.width = std::clamp(image + (image & 1), 128, 1024);
        g.height = g.width / 2;
        // About one sub-sample per texel, 2 x 2 to 3 x 3 per cell (a 4k image: 4.7M look-ups).
        g.subsamples = std::clamp((image + g.width - 1) / g.width, 2, 3);
    }
    return g;
}

bool environment_uniform(const scene::Scene& scene) {
    if (!scene.sky_sphere) return true;
    for (const scene::Pigment& p : scene.sky_sphere->pigments)
        if (p.kind != scene::PatternKind::Plain) return false;
    return true;
}

}  // namespace glint::render
