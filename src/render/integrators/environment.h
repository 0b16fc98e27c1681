// Importance sampling of the environment (the background with the sky_sphere's layers, an HDR
// image among them) for the path tracer's next-event estimation and MIS. PathLights builds one
// EnvironmentDistribution per render from the integrator's own environment radiance, so the
// table sees every pigment, transform and `emission` exactly as camera rays do.
//
// The table is an equirectangular grid over WORLD directions with +y as the pole (POV-Ray's
// map_type 1 axes): u = atan2(d.z, d.x) / 2pi in [0, 1), v = acos(d.y) / pi (v = 0 straight
// up). Each cell holds the largest luminance of k x k sub-samples plus a floor of 1e-3 times
// the mean, times sin(theta) at the cell's centre; directions are drawn from its marginal
// (rows) and conditional (columns) CDFs, continuously inside a cell (pbrt-v4's
// PiecewiseConstant2D, "Infinite Area Lights" in pbrt 4th ed. 12.5). The solid-angle pdf is
// p(u, v) / (2 pi^2 sin(theta)); the floor keeps it above zero wherever the environment has
// radiance a sub-sample missed, so the estimator stays unbiased.
//
// POV-Ray's spherical image map and Blender's world texture (measured with Blender 3.4.1 Cycles,
// tests/unit/path_lights_test.cpp, EnvironmentMatchesBlender):
// - POV-Ray map_type 1, for a direction q in the pigment's space (Y up): u = atan2(q.z, q.x)/2pi
//   (mod 1), v = 0.5 + asin(q.y)/pi, v = 1 at the image's top row.
// - Blender's Environment Texture (equirectangular), for a world direction b (Z up):
//   u = 0.5 - atan2(b.y, b.x)/2pi, v = 0.5 + asin(b.z)/pi: the image centre looks along +X,
//   +Y is at u = 0.25, v = 1 at the top row. A Mapping node rotating the vector by alpha about
//   Z adds alpha to atan2(b.y, b.x).
// - Blender's OBJ exporter (forward -Z, up Y) writes g = (b.x, b.z, -b.y), and glint's obj_file
//   mirrors z into POV-Ray's left-handed axes, so in a POV scene that places the export with
//   obj_file a Blender direction is g = (b.x, b.z, b.y) and u_blender = 0.5 - atan2(g.z, g.x)/2pi:
//   POV-Ray's u mirrored. A script writes
//     sky_sphere { pigment { image_map { exr "sky.exr" map_type 1 interpolate 2 } }
//                  scale <-1, 1, 1> rotate <0, alpha, 0> emission S }
//   for a Mapping node Z rotation of alpha degrees (leave it out for none) and a Background
//   strength S (interpolate 2 is Blender's Linear). In the OBJ file's own coordinates
//   (x, z, -y), without obj_file's mirror, the same sky is `rotate <0, 180 - alpha, 0>`.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "core/math.h"
#include "render/sampling/sampler.h"
#include "scene/scene.h"

namespace glint::render {

class TextureCache;

// A piecewise-constant density on [0, 1) over n equal bins, sampled by inverting its CDF.
class Distribution1D {
public:
    explicit Distribution1D(std::vector<double> f);
    // A point in [0, 1); *bin gets its bin, *pdf its density (with respect to [0, 1)).
    double sample(double u, int* bin, double* pdf) const;
    double pdf(int bin) const { return f_[bin] / integral_; }
    // (1 / n) * sum f: the integral of the unnormalized function.
    double integral() const { return integral_; }
    int size() const { return static_cast<int>(f_.size()); }

private:
    std::vector<double> f_;
    std::vector<double> cdf_;  // n + 1 entries, cdf_[0] = 0, cdf_[n] = 1
    double integral_ = 0;
};

struct EnvironmentGrid {
    int width = 128;
    int height = 64;
    int subsamples = 2;  // k: k x k radiance look-ups per cell, the largest kept
};

class EnvironmentDistribution {
public:
    using Radiance = std::function<Color(const Vec3&)>;
    EnvironmentDistribution(const Radiance& radiance, const EnvironmentGrid& grid);

    // A unit world direction and its solid-angle pdf; false where the pdf is not finite
    // and positive (exactly at a pole).
    bool sample(Sample2 u, Vec3* dir, double* pdf) const;
    // Solid-angle pdf of sample() producing `dir` (unit).
    double pdf(const Vec3& dir) const;

    int width() const { return width_; }
    int height() const { return height_; }
    // The grid's parameterization (see the header comment).
    static Vec3 direction(double u, double v);
    static void coordinates(const Vec3& dir, double* u, double* v);

private:
    int width_ = 0, height_ = 0;
    std::vector<Distribution1D> rows_;  // conditional density of u in each row
    std::optional<Distribution1D> marginal_;
};

// The grid for a scene's environment: as wide as the largest image in the sky_sphere (128 to
// 1024 columns, twice as many as rows), 128 x 64 otherwise; more sub-samples per cell when the
// image has more texels than the grid has cells.
EnvironmentGrid environment_grid(const scene::Scene& scene, const TextureCache* textures);

// Whether the environment is the same in every direction: no sky_sphere, or one of plain
// pigments only. Such environments keep uniform sphere sampling.
bool environment_uniform(const scene::Scene& scene);

}  // namespace glint::render
