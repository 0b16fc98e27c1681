// Normal perturbation: POV-Ray 3.7's Perturb_Normal (backend/texture/normal.cpp). Patterns with
// a direct perturbation (bumps, dents, ripples, waves, wrinkles, quilted, facets) go through
// special_normal(), bump_map by its image heights; every other pattern bends the normal by the slope of its value, sampled at
// four points of a tetrahedron `accuracy` apart and shaped by the slope_map; normal_map, block
// pattern entries and average blend the normals of their entries. Used by the Whitted integrator
// for every textured surface point.
#pragma once

#include "render/textures/pattern.h"
#include "render/textures/pigment.h"
#include "scene/texture.h"

namespace glint::render {

// Perturbs the unit normal `n` (world space, or the enclosing patterned texture's space) by
// `normal` evaluated at `at`. Returns a unit normal. A Plain normal returns `n` unchanged.
// `textures` holds the bump_map images (may be null when there are none).
Vec3 perturb_normal(const scene::Normal& normal, const PatternPoint& at, const Vec3& n,
                    const PatternContext& ctx, const TextureCache* textures = nullptr);

// POV-Ray's Warp_Normal / UnWarp_Normal for a pattern: its own transform and `warp` transforms,
// normalized before and after.
Vec3 warp_normal(const Transform& head, const scene::PatternParams& params, const Vec3& n);
Vec3 unwarp_normal(const Transform& head, const scene::PatternParams& params, const Vec3& n);

}  // namespace glint::render
