// Geometric objects of the IR: each shape in its own object space (POV-Ray's definitions),
// placed by the object's transform. CSG nodes hold child objects, so the tree is a value.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "core/error.h"
#include "core/math.h"
#include "core/transform.h"

namespace glint::scene {

struct Object;

struct Sphere {
    Vec3 center{0, 0, 0};
    double radius = 1;
};
// Points p with dot(p, normal) = distance; the inside is where dot(p, normal) < distance.
struct Plane {
    Vec3 normal{0, 1, 0};
    double distance = 0;
};
struct Box {
    Vec3 corner1{-1, -1, -1};
    Vec3 corner2{1, 1, 1};
};
struct Cylinder {
    Vec3 base{0, 0, 0};
    Vec3 cap{0, 1, 0};
    double radius = 1;
    bool open = false;
};
struct Cone {
    Vec3 base{0, 0, 0};
    double base_radius = 1;
    Vec3 cap{0, 1, 0};
    double cap_radius = 0;
    bool open = false;
};
struct Disc {
    Vec3 center{0, 0, 0};
    Vec3 normal{0, 1, 0};
    double radius = 1;
    double hole_radius = 0;
};
// In the xz-plane around the origin (POV-Ray's torus).
struct Torus {
    double major = 1;
    double minor = 0.25;
    bool sturm = false;
};
struct Triangle {
    Vec3 p[3];
};
struct SmoothTriangle {
    Vec3 p[3];
    Vec3 n[3];
};
// A triangle mesh stored in Scene::meshes.
struct MeshRef {
    int mesh = -1;
};

enum class CsgOp { Union, Merge, Intersection, Difference };

struct Csg {
    CsgOp op = CsgOp::Union;
    std::vector<Object> children;
};

using Shape = std::variant<Sphere, Plane, Box, Cylinder, Cone, Disc, Torus, Triangle,
                           SmoothTriangle, MeshRef, Csg>;

// Names for messages and `glint ir`, in variant order.
const char* shape_name(const Shape& shape);

struct Object {
    Shape shape;
    Transform transform;  // object space -> world (for CSG children: -> parent space)
    // Index into Scene::materials. -1: inherit from the enclosing CSG object; top-level
    // objects always have one (the importer applies POV-Ray's #default texture).
    int material = -1;
    bool inverse = false;
    bool hollow = false;
    bool no_shadow = false;
    bool no_image = false;
    bool no_reflection = false;
    bool double_illuminate = false;
    std::vector<Object> bounded_by;  // in this object's parent space, like the object
    std::vector<Object> clipped_by;
    std::string name;  // the #declare'd identifier it came from, if any
    FileLoc loc;
};

}  // namespace glint::scene
