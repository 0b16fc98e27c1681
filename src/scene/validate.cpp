#include "scene/validate.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace glint::scene {
namespace {

[[noreturn]] void fail(const FileLoc& loc, const std::string& message) {
    throw Error(ErrorKind::Scene, loc, message);
}

void check_finite(const Vec3& v, const FileLoc& loc, const char* what) {
    if (!is_finite(v)) fail(loc, std::string(what) + " is not a finite vector");
}

void check_finite(double v, const FileLoc& loc, const char* what) {
    if (!std::isfinite(v)) fail(loc, std::string(what) + " is not a finite number");
}

void container(const Container& c, const FileLoc& loc, const std::string& shape) {
    check_finite(c.corner1, loc, (shape + " container").c_str());
    check_finite(c.corner2, loc, (shape + " container").c_str());
    check_finite(c.center, loc, (shape + " container").c_str());
    check_finite(c.radius, loc, (shape + " container radius").c_str());
}

class Validator {
public:
    explicit Validator(const Scene& s) : scene_(s) {}

    void run() {
        camera(scene_.camera);
        for (const Light& l : scene_.lights) light(l);
        for (const Material& m : scene_.materials) material(m);
        for (const Object& o : scene_.objects) object(o, /*top_level=*/true);
    }

private:
    void camera(const Camera& c) {
        check_finite(c.location, c.loc, "camera location");
        check_finite(c.direction, c.loc, "camera direction");
        check_finite(c.right, c.loc, "camera right");
        check_finite(c.up, c.loc, "camera up");
        if (length_squared(c.direction) == 0) fail(c.loc, "camera direction has zero length");
        if (length_squared(c.right) == 0) fail(c.loc, "camera right vector has zero length");
        if (length_squared(c.up) == 0) fail(c.loc, "camera up vector has zero length");
        if (length_squared(cross(c.right, c.up)) == 0)
            fail(c.loc, "camera right and up vectors are parallel");
    }

    void light(const Light& l) {
        check_finite(l.location, l.loc, "light location");
        if (!std::isfinite(l.color.r) || !std::isfinite(l.color.g) || !std::isfinite(l.color.b))
            fail(l.loc, "light color is not finite");
        if ((l.parallel || l.kind != LightKind::Point) && l.point_at == l.location)
            fail(l.loc, "light point_at equals its location: the direction is undefined");
        if (l.fade_distance < 0) fail(l.loc, "fade_distance must not be negative");
    }

    void material(const Material& m) {
        const Finish& f = m.texture.finish;
        check_finite(f.diffuse, f.loc, "diffuse");
        if (f.phong_size < 0) fail(f.loc, "phong_size must not be negative");
        if (f.roughness < 0) fail(f.loc, "roughness must not be negative");
        if (!(m.interior.ior > 0)) fail(m.loc, "ior must be positive");
        pigment(m.texture.pigment);
    }

    void pigment(const Pigment& p) {
        if (p.kind == PatternKind::ImageMap && p.params.image.resolved_path.empty())
            fail(p.params.image.loc, "image_map file '" + p.params.image.file + "' not resolved");
        for (const Pigment& e : p.entries) pigment(e);
    }

    void object(const Object& o, bool top_level) {
        if (top_level && o.material < 0)
            fail(o.loc, "internal: top-level object without a material");
        if (o.material >= static_cast<int>(scene_.materials.size()))
            fail(o.loc, "material id out of range");
        // `scale <1, 1e300 * 1e300 - 1e300 * 1e300, 1>` (NaN) would reach the film.
        for (const Matrix4* m : {&o.transform.matrix(), &o.transform.inverse_matrix()})
            for (const auto& row : m->m)
                for (double x : row)
                    if (!std::isfinite(x))
                        fail(o.loc, "the object's transformation is not finite (NaN or "
                                    "infinity in a scale, rotate, translate or matrix)");
        std::visit([&](const auto& s) { shape(s, o.loc); }, o.shape);
        for (const Object& c : o.bounded_by) object(c, false);
        for (const Object& c : o.clipped_by) object(c, false);
    }

    void shape(const Sphere& s, const FileLoc& loc) {
        check_finite(s.center, loc, "sphere center");
        if (!(s.radius > 0)) fail(loc, "sphere radius must be positive");
    }
    void shape(const Plane& s, const FileLoc& loc) {
        check_finite(s.normal, loc, "plane normal");
        check_finite(s.distance, loc, "plane distance");
        if (length_squared(s.normal) == 0) fail(loc, "plane normal has zero length");
    }
    void shape(const Box& s, const FileLoc& loc) {
        check_finite(s.corner1, loc, "box corner");
        check_finite(s.corner2, loc, "box corner");
    }
    void shape(const Cylinder& s, const FileLoc& loc) {
        check_finite(s.base, loc, "cylinder base");
        check_finite(s.cap, loc, "cylinder cap");
        if (!(s.radius > 0)) fail(loc, "cylinder radius must be positive");
        if (s.base == s.cap) fail(loc, "cylinder base and cap points coincide");
    }
    void shape(const Cone& s, const FileLoc& loc) {
        check_finite(s.base, loc, "cone base");
        check_finite(s.cap, loc, "cone cap");
        if (s.base_radius < 0 || s.cap_radius < 0) fail(loc, "cone radius must not be negative");
        if (s.base_radius == 0 && s.cap_radius == 0) fail(loc, "cone has two zero radii");
        if (s.base == s.cap) fail(loc, "cone base and cap points coincide");
    }
    void shape(const Disc& s, const FileLoc& loc) {
        check_finite(s.center, loc, "disc center");
        if (length_squared(s.normal) == 0) fail(loc, "disc normal has zero length");
        if (!(s.radius > 0)) fail(loc, "disc radius must be positive");
        if (s.hole_radius < 0) fail(loc, "disc hole radius must not be negative");
    }
    void shape(const Torus& s, const FileLoc& loc) {
        if (!(s.major > 0) || !(s.minor > 0)) fail(loc, "torus radii must be positive");
    }
    void shape(const Triangle& s, const FileLoc& loc) {
        for (const Vec3& p : s.p) check_finite(p, loc, "triangle vertex");
    }
    void shape(const SmoothTriangle& s, const FileLoc& loc) {
        for (const Vec3& p : s.p) check_finite(p, loc, "smooth_triangle vertex");
    }
    void shape(const MeshRef& s, const FileLoc& loc) {
        if (s.mesh < 0 || s.mesh >= static_cast<int>(scene_.meshes.size()))
            fail(loc, "internal: mesh id out of range");
        const Mesh& m = scene_.meshes[s.mesh];
        const int nv = static_cast<int>(m.positions.size());
        const int nn = static_cast<int>(m.normals.size());
        const int nt = static_cast<int>(m.uvs.size());
        const int nm = static_cast<int>(scene_.materials.size());
        for (const MeshFace& f : m.faces) {
            for (int i = 0; i < 3; ++i) {
                if (f.v[i] < 0 || f.v[i] >= nv) fail(m.loc, "mesh vertex index out of range");
                if (f.n[i] >= nn) fail(m.loc, "mesh normal index out of range");
                if (f.uv[i] >= nt) fail(m.loc, "mesh uv index out of range");
            }
            if (f.material >= nm) fail(m.loc, "mesh material index out of range");
        }
    }
    void shape(const Quadric& s, const FileLoc& loc) {
        check_finite(s.square, loc, "quadric coefficient");
        check_finite(s.mixed, loc, "quadric coefficient");
        check_finite(s.linear, loc, "quadric coefficient");
        check_finite(s.constant, loc, "quadric coefficient");
    }
    void shape(const Polygon& s, const FileLoc& loc) {
        if (s.points.size() < 3) fail(loc, "polygon needs at least 3 points");
        for (const Vec3& p : s.points) check_finite(p, loc, "polygon point");
    }
    void points2(const std::vector<Vec2>& pts, const FileLoc& loc, const char* what) {
        for (const Vec2& p : pts)
            if (!std::isfinite(p.x) || !std::isfinite(p.y))
                fail(loc, std::string(what) + " point is not finite");
    }
    void shape(const Prism& s, const FileLoc& loc) {
        points2(s.points, loc, "prism");
        check_finite(s.height1, loc, "prism height");
        check_finite(s.height2, loc, "prism height");
    }
    void shape(const Lathe& s, const FileLoc& loc) { points2(s.points, loc, "lathe"); }
    void shape(const Sor& s, const FileLoc& loc) {
        points2(s.points, loc, "sor");
        if (s.points.size() < 4) fail(loc, "sor needs at least 4 points");
    }
    void shape(const Superellipsoid& s, const FileLoc& loc) {
        if (!(s.e > 0) || !(s.n > 0) || !std::isfinite(s.e) || !std::isfinite(s.n))
            fail(loc, "superellipsoid exponents must be positive");
    }
    void shape(const Blob& s, const FileLoc& loc) {
        check_finite(s.threshold, loc, "blob threshold");
        if (s.components.empty()) fail(loc, "blob needs at least one component");
        for (const BlobComponent& c : s.components) {
            check_finite(c.center, loc, "blob component");
            check_finite(c.apex, loc, "blob component");
            check_finite(c.radius, loc, "blob component radius");
            check_finite(c.strength, loc, "blob component strength");
            if (c.material >= static_cast<int>(scene_.materials.size()))
                fail(loc, "blob component material id out of range");
        }
    }
    void shape(const HeightField& s, const FileLoc& loc) {
        check_finite(s.water_level, loc, "height_field water_level");
        if (!s.heights.empty() && (s.grid_w < 2 || s.grid_h < 2 ||
                                   s.heights.size() != static_cast<size_t>(s.grid_w) * s.grid_h))
            fail(loc, "internal: height_field grid size does not match its heights");
    }
    void shape(const Poly& s, const FileLoc& loc) {
        int n = (s.order + 1) * (s.order + 2) * (s.order + 3) / 6;
        if (s.order < 2 || static_cast<int>(s.coefficients.size()) != n)
            fail(loc, "internal: poly coefficient count does not match its order");
        for (double c : s.coefficients) check_finite(c, loc, "poly coefficient");
    }
    void shape(const Text& s, const FileLoc& loc) {
        check_finite(s.thickness, loc, "text thickness");
        check_finite(s.offset, loc, "text offset");
    }
    void shape(const JuliaFractal& s, const FileLoc& loc) {
        for (int i = 0; i < 4; ++i) {
            check_finite(s.c[i], loc, "julia_fractal parameter");
            check_finite(s.slice[i], loc, "julia_fractal slice");
        }
        check_finite(s.slice_distance, loc, "julia_fractal slice distance");
        if (s.slice[3] == 0) fail(loc, "julia_fractal slice t component is zero");
        if (s.max_iteration < 1 || !(s.precision >= 1))
            fail(loc, "julia_fractal needs max_iteration >= 1 and precision >= 1");
        if (s.algebra == JuliaAlgebra::Quaternion && s.function != JuliaFunction::Sqr &&
            s.function != JuliaFunction::Cube)
            fail(loc, "julia_fractal: quaternion supports only sqr and cube");
    }
    void shape(const BicubicPatch& s, const FileLoc& loc) {
        for (const auto& row : s.points)
            for (const Vec3& p : row) check_finite(p, loc, "bicubic_patch control point");
        check_finite(s.flatness, loc, "bicubic_patch flatness");
        if (s.u_steps > 12 || s.v_steps > 12) fail(loc, "bicubic_patch steps must be at most 12");
    }
    void shape(const Isosurface& s, const FileLoc& loc) {
        if (s.function < 0 || s.function >= static_cast<int>(scene_.functions.size()))
            fail(loc, "isosurface function out of range");
        container(s.container, loc, "isosurface");
        check_finite(s.threshold, loc, "isosurface threshold");
        if (!(s.accuracy > 0) || !(s.max_gradient > 0) || !std::isfinite(s.accuracy) ||
            !std::isfinite(s.max_gradient) || s.max_trace < 1)
            fail(loc, "isosurface accuracy, max_gradient and max_trace must be positive");
    }
    void shape(const SphereSweep& s, const FileLoc& loc) {
        size_t least = s.spline == SweepSpline::Linear ? 2 : 4;
        if (s.spheres.size() < least)
            fail(loc, "sphere_sweep needs at least " + std::to_string(least) + " spheres");
        for (const Sphere& c : s.spheres) {
            check_finite(c.center, loc, "sphere_sweep centre");
            check_finite(c.radius, loc, "sphere_sweep radius");
            if (c.radius < 0) fail(loc, "sphere_sweep radius is negative");
        }
        check_finite(s.tolerance, loc, "sphere_sweep tolerance");
    }
    void shape(const Ovus& s, const FileLoc& loc) {
        check_finite(s.bottom_radius, loc, "ovus radius");
        check_finite(s.top_radius, loc, "ovus radius");
        if (!(s.bottom_radius > 0) || s.top_radius < 0 || !(s.top_radius < 2 * s.bottom_radius))
            fail(loc, "ovus radii must satisfy bottom > 0 and 0 <= top < 2 bottom");
    }
    void shape(const Parametric& s, const FileLoc& loc) {
        for (int f : s.function)
            if (f < 0 || f >= static_cast<int>(scene_.functions.size()))
                fail(loc, "parametric function out of range");
        check_finite(s.uv_min.x, loc, "parametric uv range");
        check_finite(s.uv_min.y, loc, "parametric uv range");
        check_finite(s.uv_max.x, loc, "parametric uv range");
        check_finite(s.uv_max.y, loc, "parametric uv range");
        container(s.container, loc, "parametric");
        if (!(s.accuracy > 0) || !(s.max_gradient > 0) || !std::isfinite(s.accuracy) ||
            !std::isfinite(s.max_gradient))
            fail(loc, "parametric accuracy and max_gradient must be positive");
        if (s.precompute_depth < 0 || s.precompute_depth > 20)
            fail(loc, "parametric precompute depth must be 1 to 20");
    }
    void shape(const Csg& s, const FileLoc&) {
        for (const Object& c : s.children) object(c, false);
    }

    const Scene& scene_;
};

}  // namespace

void validate(const Scene& scene) { Validator(scene).run(); }

}  // namespace glint::scene
