// Triangle meshes (POV-Ray mesh/mesh2, OBJ). Indexed so that a million triangles cost a few
// dozen bytes each; per-face material ids point into Scene::materials.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/math.h"

namespace glint::scene {

struct MeshFace {
    std::array<int, 3> v{-1, -1, -1};
    std::array<int, 3> n{-1, -1, -1};   // -1: flat (use the geometric normal)
    std::array<int, 3> uv{-1, -1, -1};  // -1: no texture coordinates
    int material = -1;                  // -1: the mesh object's material
};

// A named value per face corner beside the mesh's own: Blender's UV maps and colour
// attributes, which the Attribute, Color Attribute and UV Map nodes read by name, and the
// MikkTSpace tangents Blender computes for a UV map (named as the map), which the Normal Map
// node reads in tangent space.
struct MeshAttribute {
    enum class Kind { UV, Color, Tangent };
    std::string name;
    Kind kind = Kind::Color;
    bool active_render = false;  // the layer a node with no name reads
    std::vector<Vec3> values;    // per corner (Mesh::corners), uv as (u, v, 0)
    bool per_triangle_corner = false;  // values[3 face + k] instead (Cycles' tangents)
    std::vector<float> alpha;    // colours: per corner, empty means 1; tangents: the sign
                                 // of the bitangent per corner
};

struct Mesh {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;
    std::vector<Vec2> uvs;
    std::vector<MeshFace> faces;
    // POV-Ray's inside_vector: lets a closed mesh take part in CSG.
    bool has_inside_vector = false;
    Vec3 inside_vector{0, 0, 1};
    // Blender's texture space (Generated coordinates: (p - location) / (2 size) + 0.5 in
    // object space); unset for POV-Ray and OBJ meshes, which then use their bounds.
    bool has_texspace = false;
    Vec3 texspace_location{0, 0, 0};
    Vec3 texspace_size{1, 1, 1};
    // Per face, the corner of each of its three vertices into the attributes' values; empty
    // when there are none.
    std::vector<MeshAttribute> attributes;
    std::vector<std::array<int, 3>> corners;
    // Deformation motion blur (Blender's armatures, shape keys, modifiers): the positions, and
    // normals where the mesh has them, at evenly spaced shutter times i / (steps - 1), each
    // step as long as `positions` (`normals`). A ray at time t meets the faces of the vertices
    // interpolated linearly between the two steps about it, as Cycles' motion triangles do.
    // Empty: the mesh does not deform.
    std::vector<std::vector<Vec3>> motion_positions;
    std::vector<std::vector<Vec3>> motion_normals;
    std::string name;  // the OBJ object or group ("" for POV-Ray's meshes): named in warnings
    FileLoc loc;
};

}  // namespace glint::scene
