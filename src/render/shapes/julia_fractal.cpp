// julia_fractal (POV-Ray 3.7 manual 2.4.1.5; fractal.cpp): the ray is marched through the
// bounding sphere by the orbit's step estimate (never less than 1 / precision) until a step
// lands on the other side of the set's boundary; bisection then narrows the crossing to
// 1e-7, and the normal comes from the orbit of the point on the set's side. The march keeps
// POV-Ray's depth bookkeeping, including that after a crossing the next depths are counted
// from the crossing rather than from where the march resumes: CSG sees the same hits. Hits
// carry no offset for rays that leave them: as in POV-Ray, such a ray starts on the set's
// side and the crossing it finds at once is dropped (MIN_ISECT_DEPTH).
#include <algorithm>
#include <cmath>

#include "render/shapes/julia_orbit.h"
#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

using julia::Orbit;
using julia::OrbitStack;

constexpr double kTolerance = 1e-7;  // fractal.cpp's Fractal_Tolerance
constexpr double kEpsilon = 1e-10;   // POV-Ray's EPSILON
constexpr double kMinDepth = 1e-4;   // POV-Ray's MIN_ISECT_DEPTH

class JuliaFractalPrim final : public Primitive {
public:
    JuliaFractalPrim(const scene::JuliaFractal& s, const Transform& xf) : orbit_(s), xf_(xf) {}

    Bounds3 bounds() const override {
        const double r = orbit_.radius();
        return {Vec3(-r), Vec3(r)};
    }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        HitList hits;
        march(ray, tmax, true, &hits);
        if (hits.empty()) return false;
        *hit = hits[0];
        return true;
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        march(ray, tmax, false, hits);
    }

    bool inside(const Vec3& p) const override {
        OrbitStack stack(orbit_.iterations());
        return orbit_.stays(p, stack.data());
    }

private:
    // POV-Ray's sphere test (spheres.cpp): no hit when the ray starts outside and points
    // away, or only grazes.
    bool bound(const Vec3& o, const Vec3& d, double* t0, double* t1) const {
        const double r2 = orbit_.radius() * orbit_.radius();
        const Vec3 oc = -o;
        const double oc2 = dot(oc, oc), closest = dot(oc, d);
        if (oc2 >= r2 && closest < kEpsilon) return false;
        const double half2 = r2 - oc2 + closest * closest;
        if (!(half2 > kEpsilon)) return false;
        const double half = std::sqrt(half2);
        *t0 = closest - half;
        *t1 = closest + half;
        return true;
    }

    // POV-Ray's All_Intersections: the crossings in order; `first_only` stops at the first.
    void march(const Ray& ray, double tmax, bool first_only, HitList* hits) const {
        const double len = length(ray.dir);
        if (!(len > 0) || !std::isfinite(len)) return;
        const Vec3 dir = ray.dir / len;
        // Object units to the placing space's along this ray (MIN_ISECT_DEPTH is in world
        // units; the transforms of enclosing CSG are not known here).
        const double scale = length(xf_.vector(dir));
        double depth, depth_max;
        if (!bound(ray.origin, dir, &depth, &depth_max)) return;
        if (depth_max < kTolerance) return;
        if (depth < kTolerance) depth = kTolerance;
        OrbitStack stack(orbit_.iterations());
        Vec3 next = ray.origin + dir * depth;
        double step, step_next = 0;
        bool current = orbit_.stays_with_step(next, dir, &step, stack.data());
        if (current) {  // starting inside: step off the surface the ray may have left
            next = next + dir * (2.0 * kTolerance);
            depth += 2.0 * kTolerance;
            if (depth > depth_max) return;
            current = orbit_.stays_with_step(next, dir, &step, stack.data());
        }
        bool last = false;
        while (depth < depth_max) {
            Vec3 at;
            bool after;
            for (;;) {  // march until a step crosses the boundary
                step = std::max(step, orbit_.min_step());
                depth += step;
                if (depth > depth_max) return;
                at = next;
                next = next + dir * step;
                after = orbit_.stays_with_step(next, dir, &step_next, stack.data());
                if (after != current) {
                    depth -= step;
                    break;
                }
                step = step_next;
            }
            while (step > kTolerance) {  // bisect, keeping `at` on the starting side
                step *= 0.5;
                const Vec3 mid = at + dir * step;
                last = orbit_.stays(mid, stack.data());
                if (last == current) {
                    at = mid;
                    depth += step;
                    if (depth > depth_max) return;
                }
            }
            // The hit point is the one on the set's side; its orbit gives the normal.
            if (!current) {
                at = at + dir * step;
                depth += step;
                orbit_.stays(at, stack.data());
            } else if (last != current) {
                orbit_.stays(at, stack.data());
            }
            const double t = depth / len;
            // POV-Ray's MIN_ISECT_DEPTH: a crossing this close is dropped by its caller, and
            // outside CSG it is the only one the fractal reports, so the ray sees none.
            if (depth * scale < kMinDepth) {
                if (first_only) return;
                step = step_next;
                current = after;
                continue;
            }
            if (t > 0 && t < tmax) {
                LocalHit& h = hits->emplace_back();
                h.t = t;
                h.p = at;
                // Only rounding: rays leaving the surface start where POV-Ray's do (on the
                // set's side), and the march's dropped near crossing keeps them off it.
                h.p_error = rounding_error(at, 8);
                Vec3 n = orbit_.normal(orbit_.iterations(), stack.data());
                const double nl = length(n);
                n = nl > 0 && std::isfinite(nl) ? n / nl : -dir;
                h.ng = n;
                h.n = n;
            }
            if (first_only) return;
            step = step_next;
            current = after;
        }
    }

    Orbit orbit_;
    Transform xf_;
};

}  // namespace

std::unique_ptr<Primitive> make_julia_fractal(const scene::JuliaFractal& s, const Transform& xf,
                                              const char** why) {
    bool finite = std::isfinite(s.slice_distance) && std::isfinite(s.precision);
    for (int i = 0; i < 4; ++i) finite = finite && std::isfinite(s.c[i]) && std::isfinite(s.slice[i]);
    if (!finite || s.slice[3] == 0 || s.max_iteration < 1 || !(s.precision >= 1)) {
        *why = "julia_fractal with a zero slice t, non-finite numbers or no iterations";
        return nullptr;
    }
    return std::make_unique<JuliaFractalPrim>(s, xf);
}

}  // namespace glint::render
