// Geometric objects of the IR: each shape in its own object space (POV-Ray's definitions),
// placed by the object's transform. CSG nodes hold child objects, so the tree is a value.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <utility>
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
    MeshRef() = default;
    MeshRef(int m) : mesh(m) {}  // NOLINT: MeshRef{id} names a mesh
    int mesh = -1;
    // This object's materials for the faces' own (face material id -> material id): POV-Ray
    // transforms a mesh's texture_list textures with the mesh, so each transformed copy of the
    // mesh has its own transformed copies of them. Empty: the faces' as they are.
    std::vector<std::pair<int, int>> face_materials;
};

// quadric (POV-Ray 3.7 manual 2.4.3.5): A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y +
// I z + J = 0; the inside is where the left side is <= 0.
struct Quadric {
    Vec3 square{1, 1, 1};  // A, B, C
    Vec3 mixed{0, 0, 0};   // D (xy), E (xz), F (yz)
    Vec3 linear{0, 0, 0};  // G, H, I
    double constant = -1;  // J
};
// polygon: coplanar points; a point equal to its sub-polygon's first point closes it, and the
// next point starts another (holes by the even-odd rule). The importer closes an open list.
struct Polygon {
    std::vector<Vec3> points;
};
enum class SplineType { Linear, Quadratic, Cubic, Bezier };
// prism: a closed 2D spline in the xz-plane (points as <x, z>) swept along y between the heights;
// a conic sweep scales the outline by y (apex at the origin).
struct Prism {
    SplineType spline = SplineType::Linear;
    bool conic = false;
    double height1 = 0, height2 = 1;  // height1 <= height2
    std::vector<Vec2> points;
    bool open = false;
    bool sturm = false;
};
// lathe: a 2D spline of <radius, height> points revolved around the y axis.
struct Lathe {
    SplineType spline = SplineType::Linear;
    std::vector<Vec2> points;
    bool sturm = false;
};
// sor: radius^2 as a cubic in height through <radius, height> points (the first and last only
// steer the curve's ends), revolved around y; capped unless open.
struct Sor {
    std::vector<Vec2> points;
    bool open = false;
    bool sturm = false;
};
// superellipsoid { <e, n> }: (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1.
struct Superellipsoid {
    double e = 1, n = 1;
};
// A blob component: strength * (1 - r^2 / radius^2)^2 inside radius, r the distance to the
// centre (sphere) or to the segment base-apex (cylinder, with hemispherical ends), evaluated in
// the component's own space (`transform` maps it into blob space).
struct BlobComponent {
    bool cylinder = false;
    Vec3 center{0, 0, 0};  // sphere; cylinder: base
    Vec3 apex{0, 0, 0};    // cylinder only
    double radius = 1;
    double strength = 1;
    Transform transform;
    // The component's own texture, as the texture of this Scene::materials id (its interior
    // is unused); -1: the blob's. Where components have textures, a hit blends the textures
    // of the components whose field reaches it, weighted by |field| (blob.cpp's
    // Determine_Textures).
    int material = -1;
};
// blob: the surface where the summed field equals threshold; inside where it is larger.
struct Blob {
    double threshold = 1;
    std::vector<BlobComponent> components;
    bool sturm = false;
};
// height_field: an image's heights (0..1) on the unit square x, z in [0, 1], image row 0 at z = 1.
struct HeightField {
    std::string file;           // as written in the scene
    std::string resolved_path;  // found by the importer
    // `pot "file"`: a Fractint .pot file, a GIF whose left half holds the heights' high bytes
    // and right half their low bytes (POV-Ray's gif.cpp), as palette indices.
    bool pot = false;
    // `function W, H { ... }`: the heights the importer evaluated, grid_w x grid_h values in
    // POV-Ray's 1/65536 units, row z = 0 first. As for images, the function's row y = 0 lies
    // at z = 1 (POV-Ray builds an image from the function); no file then.
    int grid_w = 0, grid_h = 0;
    std::vector<uint16_t> heights;
    bool smooth = false;
    double water_level = 0;     // heights below it are cut away
    FileLoc file_loc;
};
// poly/cubic/quartic: sum of c_ijk x^i y^j z^k = 0, i + j + k <= order, coefficients in
// POV-Ray's order (x power descending, then y, then z); inside where the sum < 1e-4.
struct Poly {
    int order = 2;
    std::vector<double> coefficients;
    bool sturm = false;
};

// julia_fractal (POV-Ray 3.7 manual 2.4.1.5; fractal.cpp, quatern.cpp, hcmplx.cpp): the 3D
// slice of a 4D Julia set of z -> f(z) + c, the points whose orbit stays inside the escape
// radius for max_iteration steps. Quaternion algebra takes sqr and cube only.
enum class JuliaAlgebra { Quaternion, Hypercomplex };
// In POV-Ray's order (its STYPE list): the hypercomplex functions apply a complex one.
enum class JuliaFunction {
    Exp, Ln, Sin, Asin, Cos, Acos, Tan, Atan, Sinh, Asinh, Cosh, Acosh, Tanh, Atanh, Pwr,
    Sqr, Cube, Reciprocal
};
struct JuliaFractal {
    double c[4] = {1, 0, 0, 0};  // the Julia parameter <x, y, z, t>
    JuliaAlgebra algebra = JuliaAlgebra::Quaternion;
    JuliaFunction function = JuliaFunction::Sqr;
    Vec2 exponent{0, 0};  // pwr's complex exponent
    int max_iteration = 20;
    double precision = 20;  // the march never steps less than 1 / precision
    // The slice: the 4D points with dot(slice, p) = slice_distance, slice a unit vector whose
    // t component is not zero (the importer normalizes it).
    double slice[4] = {0, 0, 0, 1};
    double slice_distance = 0;
};

// bicubic_patch (POV-Ray 3.7 manual 2.4.3.1; bezier.cpp): a Bezier patch of 4 x 4 control
// points (row i runs along u, column j along v), cut into flat pieces up to u_steps / v_steps
// halvings and rendered as their triangles with normals interpolated from the patch. Types
// 0 and 1 give the same surface (POV-Ray cuts per ray or once).
struct BicubicPatch {
    int type = 1;
    double flatness = 0;
    int u_steps = 0, v_steps = 0;
    Vec3 points[4][4];
    Vec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // uv_vectors: the corners' texture uv
};

// The contained_by of an isosurface or parametric: a box (corners sorted, corner1 <= corner2),
// or a sphere when `sphere`.
struct Container {
    bool sphere = false;
    Vec3 corner1{-1, -1, -1}, corner2{1, 1, 1};
    Vec3 center{0, 0, 0};
    double radius = 1;
    // A box with its corners in order, or a sphere of positive radius.
    bool valid() const {
        return sphere ? radius > 0
                      : corner1.x <= corner2.x && corner1.y <= corner2.y && corner1.z <= corner2.z;
    }
};

// isosurface (POV-Ray 3.7 manual 2.4.2.3): the surface where Scene::functions[function](x, y, z)
// equals threshold, inside where it is lower, cut to its container (a box, or a sphere when
// `sphere`); the root search steps by max_gradient and stops at accuracy (POV-Ray's isosurf.cpp).
struct Isosurface {
    int function = -1;  // index into Scene::functions
    Container container;
    double threshold = 0;
    double accuracy = 0.001;
    double max_gradient = 1.1;
    int max_trace = 1;        // all_intersections: 10
    bool evaluate = false;    // evaluate P0, P1, P2: max_gradient adapted per ray
    double eval[3] = {0, 0, 0};
    bool open = false;        // no surface on the container
};

// text (POV-Ray 3.7 manual 2.4.2.7): the string's TrueType glyphs extruded from z = 0 to
// z = thickness, laid out along +x from the origin, `offset` added after each character.
struct Text {
    std::string file;  // the font as written in the scene
    std::string font;  // its resolved path
    std::string text;
    double thickness = 1;
    Vec3 offset{0, 0, 0};
};

// sphere_sweep (reference manual 3.4.5.1.13; sphsweep.cpp): a sphere moved along a spline through
// the spheres' centres, its radius following the same spline through theirs; the solid is the
// union of all the spheres it passes through. Linear: one cone-like piece per pair of spheres.
// BSpline (uniform B-spline, passing near the spheres) and Cubic (POV-Ray's Catmull-Rom, passing
// through the inner ones): one piece per four consecutive spheres, the first and last spheres
// only steering the ends. `tolerance`: POV-Ray's depth tolerance, the nearest hit distance kept.
enum class SweepSpline { Linear, BSpline, Cubic };
struct SphereSweep {
    SweepSpline spline = SweepSpline::Linear;
    std::vector<Sphere> spheres;  // at least 2 (Linear) or 4
    double tolerance = 1e-6;
};

// ovus (POV-Ray 3.7 reference 3.4.5.1.11; ovus.cpp): an egg around the y axis, a sphere of
// radius bottom_radius at the origin below, one of radius top_radius centred at
// <0, bottom_radius, 0> above, joined by a band of a spindle torus tangent to both. POV-Ray's
// parser makes a sphere of it when top_radius >= 2 bottom_radius, and so does the importer.
struct Ovus {
    double bottom_radius = 1;
    double top_radius = 0.5;  // 0 <= top_radius < 2 bottom_radius
};

// parametric (POV-Ray 3.7 reference 3.4.5.1.10; fpmetric.cpp): the surface
// <fx(u, v), fy(u, v), fz(u, v)> (Scene::functions[function[i]], called with x = u, y = v,
// z = 0) for u, v in [uv_min, uv_max], found by subdividing that rectangle within the container
// (a box, or a sphere when `sphere`) down to `accuracy`, each piece's range bounded by
// max_gradient. precompute[i]: the ranges of coordinate i over the first 2^precompute_depth
// pieces are computed once. No inside.
struct Parametric {
    int function[3] = {-1, -1, -1};
    Vec2 uv_min{0, 0}, uv_max{1, 1};  // uv_min <= uv_max
    Container container;
    double accuracy = 0.001;
    double max_gradient = 1;
    int precompute_depth = 0;  // 1 to 20 when any of `precompute` is set
    bool precompute[3] = {false, false, false};
};

enum class CsgOp { Union, Merge, Intersection, Difference };

struct Csg {
    CsgOp op = CsgOp::Union;
    std::vector<Object> children;
};

using Shape = std::variant<Sphere, Plane, Box, Cylinder, Cone, Disc, Torus, Triangle,
                           SmoothTriangle, MeshRef, Csg, Quadric, Polygon, Prism, Lathe, Sor,
                           Superellipsoid, Blob, HeightField, Poly, Text, JuliaFractal,
                           BicubicPatch, Isosurface, SphereSweep, Ovus, Parametric>;

// Names for messages and `glint ir`, in variant order.
const char* shape_name(const Shape& shape);

struct Object {
    Shape shape;
    Transform transform;  // object space -> world (for CSG children: -> parent space)
    // Motion blur (Blender): object space -> world at evenly spaced shutter times 0 ... 1
    // (at least two), `transform` being the one at the frame. Empty: the object stays put.
    // Top-level mesh objects only.
    std::vector<Matrix4> motion;
    // Index into Scene::materials. -1: inherit from the enclosing CSG object; top-level
    // objects always have one (the importer applies POV-Ray's #default texture).
    int material = -1;
    bool inverse = false;
    bool hollow = false;
    bool no_shadow = false;
    bool no_image = false;
    bool no_reflection = false;
    bool double_illuminate = false;
    bool no_radiosity = false;  // invisible to radiosity's sample rays
    // POV-Ray `light_group`: the lights whose Light::group is `light_group` light this object
    // besides the global ones, and none of the global ones when `no_global_lights`. On a CSG
    // object they hold for its children too: the innermost light_group >= 0 counts, and
    // no_global_lights anywhere on the way down.
    int light_group = -1;
    bool no_global_lights = false;
    // `radiosity { importance }`: the share of a sample's rays that may hit this object
    // (0, 1]; negative: the #default importance.
    double radiosity_importance = -1;
    // `photons { target [F] refraction B reflection B pass_through collect B }`: photons are
    // shot at targets (spacing times `photon_target`; 0: not a target). -1 / 0 / 1: unset,
    // off, on (merged with the light's flags).
    double photon_target = 0;
    int photon_refraction = -1, photon_reflection = -1;
    bool photon_pass_through = false;
    bool photon_collect = true;  // false: `collect off`, no photons land on it
    // Blender's ray visibility (Object Properties > Visibility), holdout and the values the
    // Object Info node reads; POV-Ray's objects keep the defaults.
    struct RayVisibility {
        bool camera = true, diffuse = true, glossy = true, transmission = true, shadow = true;
    } visibility;
    bool holdout = false;
    Color info_color{1, 1, 1};
    double pass_index = 0;
    double random = 0;
    // A Blender Volume object: its OpenVDB file (grids in object space: the file's world is
    // the object's space), read when a volume shader asks for a grid, and its step size (0:
    // by the voxels; in object space or in world space).
    struct VolumeFile {
        std::string path;
        double step_size = 0;
        bool object_space = true;
    };
    std::optional<VolumeFile> volume_file;
    std::vector<Object> bounded_by;  // in this object's parent space, like the object
    std::vector<Object> clipped_by;
    std::string name;  // the #declare'd identifier it came from, if any
    FileLoc loc;
};

}  // namespace glint::scene
