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
// How POV-Ray's spherical image map and Blender's world texture map directions (and how the
// add-on writes a Blender world for glint): docs/pbr-mapping.md, "Blender world textures"
// (checked by path_lights_test, EnvironmentMatchesBlender).
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "core/math.h"
#include "render/sampling/distribution.h"
#include "render/sampling/sampler.h"
#include "scene/scene.h"

namespace glint::render {

class TextureCache;

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
