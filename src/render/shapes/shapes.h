// Factories for the primitives of the IR's shape variant, each in its own object space
// (POV-Ray's definitions). Shapes given by end points (cylinder, cone, disc) come back with the
// frame that places their canonical form, which the caller composes with the object transform.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "core/log.h"
#include "core/transform.h"
#include "render/shapes/primitive.h"
#include "scene/mesh.h"
#include "scene/shape.h"

namespace glint::scene {
struct Scene;
}

namespace glint::render {

// The u of POV-Ray's uv_mapping on shapes of revolution about y (sphere, lathe, sor): the
// angle of (x, z) from +x towards +z as a fraction of a turn, 0 on the axis.
inline double turn_about_y(double x, double z) {
    double len = x * x + z * z;
    if (!(len > 1e-10)) return 0;
    if (z == 0) return x > 0 ? 0.0 : 0.5;
    double theta = std::acos(std::clamp(x / std::sqrt(len), -1.0, 1.0));
    if (z < 0) theta = 2 * kPi - theta;
    return theta / (2 * kPi);
}

std::unique_ptr<Primitive> make_sphere(const scene::Sphere& s);
std::unique_ptr<Primitive> make_plane(const scene::Plane& s);
std::unique_ptr<Primitive> make_box(const scene::Box& s);
// Canonical cylinder/cone along +z from z=0 to z=1; `frame` maps it into object space.
// Returns nullptr for degenerate input (zero length or radius), with `*why` set.
std::unique_ptr<Primitive> make_cylinder(const scene::Cylinder& s, Transform* frame,
                                         const char** why);
std::unique_ptr<Primitive> make_cone(const scene::Cone& s, Transform* frame, const char** why);
std::unique_ptr<Primitive> make_disc(const scene::Disc& s, Transform* frame, const char** why);
std::unique_ptr<Primitive> make_torus(const scene::Torus& s);
std::unique_ptr<Primitive> make_triangle(const Vec3 p[3], const Vec3* normals);
// POV-Ray's other solids (quadric.cpp, polygon.cpp, prism.cpp, lathe.cpp, sor.cpp,
// superellipsoid.cpp, blob.cpp, height_field.cpp, poly.cpp). nullptr with `*why` set for
// degenerate input; the height field throws glint::Error when its image cannot be read.
std::unique_ptr<Primitive> make_quadric(const scene::Quadric& s, const char** why);
std::unique_ptr<Primitive> make_polygon(const scene::Polygon& s, const char** why);
std::unique_ptr<Primitive> make_prism(const scene::Prism& s, const char** why);
std::unique_ptr<Primitive> make_lathe(const scene::Lathe& s, const char** why);
std::unique_ptr<Primitive> make_sor(const scene::Sor& s, const char** why);
std::unique_ptr<Primitive> make_superellipsoid(const scene::Superellipsoid& s, const char** why);
std::unique_ptr<Primitive> make_blob(const scene::Blob& s, const char** why);
// `shading`: the object's transform, in whose space POV-Ray blends smooth normals.
std::unique_ptr<Primitive> make_height_field(const scene::HeightField& s, const FileLoc& loc,
                                             const Transform& shading, const char** why);
std::unique_ptr<Primitive> make_poly(const scene::Poly& s, const char** why);
// julia_fractal.cpp: nullptr with `*why` set for a zero slice t or non-finite numbers. `xf`:
// the object's transform, which only scales POV-Ray's nearest-hit depth to its units.
std::unique_ptr<Primitive> make_julia_fractal(const scene::JuliaFractal& s, const Transform& xf,
                                              const char** why);
// bicubic_patch.cpp: the patch with `xf` (its object transform) baked into the control points,
// as POV-Ray subdivides it where it stands.
std::unique_ptr<Primitive> make_bicubic_patch(const scene::BicubicPatch& s, const Transform& xf,
                                              const char** why);
// isosurface.cpp: evaluates the scene's user functions (it keeps a copy of them).
std::unique_ptr<Primitive> make_isosurface(const scene::Isosurface& s, const scene::Scene& scene,
                                           const char** why);
// sphere_sweep.cpp: nullptr with `*why` set for too few spheres or non-finite numbers.
std::unique_ptr<Primitive> make_sphere_sweep(const scene::SphereSweep& s, const char** why);
// ovus.cpp: nullptr with `*why` set unless bottom > 0 and 0 <= top < 2 bottom.
std::unique_ptr<Primitive> make_ovus(const scene::Ovus& s, const char** why);
// parametric.cpp: evaluates the scene's user functions (it keeps a copy of them). `xf`: the
// object's transform, in whose units POV-Ray measures the search's depths.
std::unique_ptr<Primitive> make_parametric(const scene::Parametric& s, const scene::Scene& scene,
                                           const Transform& xf, const char** why);
// POV-Ray's max_gradient advice after the render, one warning per isosurface that needs one.
void report_gradients(const std::vector<GradientNote>& notes, const scene::Scene& scene,
                      Diagnostics& diag);

}  // namespace glint::render

namespace glint::render {
// The frame whose z axis is `axis` (not normalized: canonical z = 1 lands on origin + axis),
// x and y unit and perpendicular (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited"). Throws glint::Error if `axis` is zero.
Transform axis_frame(const Vec3& origin, const Vec3& axis);
}  // namespace glint::render
