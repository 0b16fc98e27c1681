// Cutting an OBJ face (a polygon of three or more corners) into triangles, as Blender cuts its
// meshes for rendering. Where a smooth-shaded quad is cut decides how its normals interpolate,
// and Cycles renders Blender's own cut; tinyobjloader's (the shorter diagonal) differs on
// every quad whose diagonals are about equal, which is most quads of a torus or a subdivided
// model, and there glint's shading differed from Cycles' by up to 30% in grazing reflections.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "core/math.h"

namespace glint::obj {

// Appends the triangles of the polygon with these corners, as corner indices into `corners`,
// keeping the polygon's winding:
// - a triangle as it is;
// - a quad on its 0-2 diagonal, (0 1 2) (0 2 3), unless corners 1 and 3 lie on the same side
//   of that diagonal (the quad is bent or concave there), then on 1-3, (0 1 3) (1 2 3): the
//   rule of Blender's mesh tessellation;
// - five corners or more by ear clipping in the plane of the polygon's Newell normal, first
//   ears first, so a convex polygon becomes the fan around corner 0. A polygon with no area
//   (no normal) or of more than kMaxEarClipCorners corners becomes that fan.
void triangulate_face(std::span<const Vec3> corners, std::vector<std::array<int, 3>>* out);

// Ear clipping costs O(n^2) in a polygon's corners; past this a polygon is cut as a fan.
constexpr int kMaxEarClipCorners = 1024;

}  // namespace glint::obj
