// Deforming meshes (deformation motion blur; scene::Mesh::motion_positions): a ray at shutter
// time t meets each face with its vertices interpolated linearly between the two motion steps
// about t, as Cycles 3.4's motion triangles (geom/motion_triangle.h) do. The BVH holds each
// face's box over all steps, which holds it at every time between them.
#pragma once

#include <memory>
#include <vector>

#include "render/shapes/primitive.h"
#include "scene/mesh.h"

namespace glint::render {

// `faces`: the usable faces (mesh_prim.cpp's checks, made at the centre positions).
std::unique_ptr<Primitive> make_motion_mesh(const scene::Mesh& mesh, const std::vector<int>& faces);

}  // namespace glint::render
