// The objects that contain the camera's eye point (POV-Ray's InitRayContainerState; Cycles'
// volume stack init), for the integrators that track which interiors or media a ray is in.
#pragma once

#include <vector>

#include "render/prepare/geometry.h"
#include "scene/scene.h"

namespace glint::render {

struct Containing {
    int object;    // top-level scene object
    int material;  // the material of the surface that closes it around the eye
    bool hollow;   // that surface's shape is hollow (render/ray.h kHollow)
};

// In scene order; empty for projections whose rays do not all start at the camera location.
std::vector<Containing> objects_containing_camera(const scene::Scene& scene,
                                                  const Geometry& geometry);
// The objects around point `p`, found along a walk in direction `dir`; in scene order. A
// top-level union counts each of its materials apart: POV-Ray links a union's children to the
// scene as objects of their own (Link_To_Frame), so a hollow media sphere in a union with a
// submarine holds the eye whatever the walk meets first.
std::vector<Containing> objects_containing(const scene::Scene& scene, const Geometry& geometry,
                                           const Vec3& p, const Vec3& dir);

}  // namespace glint::render
