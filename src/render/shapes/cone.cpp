// cylinder and cone (POV-Ray 3.7 manual 2.4.1.5 and 2.4.1.3), open or closed, either cone
// radius may be 0. Both are solved in a canonical frame: axis along z from z = 0 (base) to z = 1
// (cap), radius r(z) = r0 + (r1 - r0) z, so x^2 + y^2 = r(z)^2 is one quadratic in t.
// Inside is POV-Ray's (cones.cpp, Cone::Inside): the solid, also for open ones.
#include <cmath>

#include "core/error.h"
#include "render/shapes/cone_roots.h"
#include "render/shapes/shapes.h"

namespace glint::render {

Transform axis_frame(const Vec3& origin, const Vec3& axis) {
    double len = length(axis);
    Vec3 w = axis / len;
    double sign = std::copysign(1.0, w.z);
    double a = -1.0 / (sign + w.z);
    double b = w.x * w.y * a;
    Vec3 u(1 + sign * w.x * w.x * a, sign * b, -sign * w.x);
    Vec3 v(b, sign + w.y * w.y * a, -w.y);
    Matrix4 m;
    for (int i = 0; i < 3; ++i) {
        m.m[i][0] = u[i];
        m.m[i][1] = v[i];
        m.m[i][2] = axis[i];
        m.m[i][3] = origin[i];
    }
    return Transform::from_matrix(m);
}

namespace {

// a*b - c*d with one rounding (Kahan's algorithm with FMA): the discriminant without
// catastrophic cancellation.
[[gnu::always_inline]] inline double diff_of_products(double a, double b, double c, double d) {
    double cd = c * d;
    double err = std::fma(-c, d, cd);
    double dop = std::fma(a, b, -cd);
    return dop + err;
}

// The roots, built twice: glint's build runs on any x86-64, where std::fma is a call into the C
// library (and every live register is spilled around it); the copy for CPUs with FMA has the
// instruction inline. FMA rounds once either way and cone.cpp is compiled without contraction
// into FMA (CMakeLists.txt), so both give the same bits (cone_roots_test).
[[gnu::always_inline]] inline int roots_body(const ConeShape& cone, const Ray& ray, double tmax,
                                             ConeRoot out[4]) {
    const double r0 = cone.r0, r1 = cone.r1, k = r1 - r0;
    int n = 0;
    const Vec3 &o = ray.origin, &d = ray.dir;
    double rho = r0 + k * o.z;  // radius at the origin's height
    double kd = k * d.z;
    double a = diff_of_products(d.x, d.x, kd, kd) + d.y * d.y;
    double bh = o.x * d.x + o.y * d.y - rho * kd;
    double c = diff_of_products(o.x, o.x, rho, rho) + o.y * o.y;
    double scale_c = o.x * o.x + o.y * o.y + rho * rho;
    auto side = [&](double t, double err) {
        if (!(t > err) || !(t < tmax)) return;
        double z = o.z + t * d.z;
        if (z >= 0 && z <= 1) out[n++] = {t, 0};
    };
    double scale_a = d.x * d.x + d.y * d.y + kd * kd;
    if (std::fabs(a) > gamma(4) * scale_a) {
        double disc = diff_of_products(bh, bh, a, c);
        if (disc >= 0) {
            double sd = std::sqrt(disc);
            double q = -(bh + std::copysign(sd, bh));
            if (q != 0) {
                double t_far = q / a, t_near = c / q;
                double e_near = gamma(4) * scale_c / std::fabs(q) + gamma(3) * std::fabs(t_near);
                double e_far = gamma(8) * std::fabs(t_far);
                side(t_near, e_near);
                side(t_far, e_far);
            }
        }
    } else if (bh != 0) {
        // The ray is parallel to a generating line of the cone: one root.
        double t = -c / (2 * bh);
        side(t, gamma(4) * scale_c / std::fabs(2 * bh) + gamma(3) * std::fabs(t));
    }
    if (!cone.open && d.z != 0) {
        for (int cap = 0; cap < 2; ++cap) {
            double r = cap ? r1 : r0;
            if (r <= 0) continue;
            double t = (cap - o.z) / d.z;
            if (!(t > 0) || !(t < tmax)) continue;
            double x = o.x + t * d.x, y = o.y + t * d.y;
            if (x * x + y * y <= r * r) out[n++] = {t, 1 + cap};
        }
    }
    return n;
}

int roots_generic(const ConeShape& cone, const Ray& ray, double tmax, ConeRoot out[4]) {
    return roots_body(cone, ray, tmax, out);
}

#if defined(__x86_64__)
__attribute__((target("fma"))) int roots_fma(const ConeShape& cone, const Ray& ray, double tmax,
                                             ConeRoot out[4]) {
    return roots_body(cone, ray, tmax, out);
}
#endif

class ConePrim final : public Primitive {
public:
    ConePrim(double r0, double r1, bool open)
        : shape_{r0, r1, open}, k_(r1 - r0), roots_(cone_roots()) {}

    Bounds3 bounds() const override {
        double r = std::max(shape_.r0, shape_.r1) * (1 + gamma(2));
        return {Vec3(-r, -r, 0), Vec3(r, r, 1)};
    }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        ConeRoot c[4];
        int n = roots_(shape_, ray, tmax, c);
        int best = -1;
        for (int i = 0; i < n; ++i)
            if (best < 0 || c[i].t < c[best].t) best = i;
        if (best < 0) return false;
        fill(ray, c[best], hit);
        return true;
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        ConeRoot c[4];
        int n = roots_(shape_, ray, tmax, c);
        for (int i = 0; i < n; ++i) fill(ray, c[i], &hits->emplace_back());
    }

    bool inside(const Vec3& p) const override {
        if (p.z < 0 || p.z > 1) return false;
        double r = shape_.r0 + k_ * p.z;
        return p.x * p.x + p.y * p.y <= r * r;
    }

private:
    void fill(const Ray& ray, const ConeRoot& c, LocalHit* h) const {
        Vec3 p = ray.origin + ray.dir * c.t;
        h->t = c.t;
        h->has_uv = false;
        if (c.part == 0) {
            p.z = std::clamp(p.z, 0.0, 1.0);
            double r = shape_.r0 + k_ * p.z;
            double w = std::sqrt(p.x * p.x + p.y * p.y);
            // Reproject onto the surface at this height (pbrt-v4's cylinder refinement).
            if (w > 0) {
                p.x *= r / w;
                p.y *= r / w;
            }
            double e = gamma(6) * (std::fabs(p.x) + std::fabs(p.y) + shape_.r0 + std::fabs(k_));
            h->p_error = Vec3(e) + rounding_error(p, 2);
            // Gradient of x^2 + y^2 - r(z)^2; at the apex (r = 0) the axis direction.
            Vec3 g(p.x, p.y, -k_ * r);
            h->ng = length_squared(g) > 0 ? normalize(g) : Vec3(0, 0, k_ < 0 ? 1 : -1);
        } else {
            p.z = c.part == 1 ? 0.0 : 1.0;
            h->p_error = rounding_error(p, 2);
            h->ng = Vec3(0, 0, c.part == 1 ? -1 : 1);
        }
        h->p = p;
        h->n = h->ng;
    }

    ConeShape shape_;
    double k_;  // r1 - r0
    ConeRootsFn roots_;
};

}  // namespace

ConeRootsFn cone_roots_generic() { return roots_generic; }

ConeRootsFn cone_roots_fma() {
#if defined(__x86_64__)
    if (__builtin_cpu_supports("fma")) return roots_fma;
#endif
    return nullptr;
}

ConeRootsFn cone_roots() {
    static const ConeRootsFn best = cone_roots_fma() ? cone_roots_fma() : cone_roots_generic();
    return best;
}

std::unique_ptr<Primitive> make_cylinder(const scene::Cylinder& s, Transform* frame,
                                         const char** why) {
    Vec3 axis = s.cap - s.base;
    if (!is_finite(s.base) || !is_finite(s.cap) || !std::isfinite(s.radius) ||
        !(length_squared(axis) > 0) || !(s.radius != 0)) {
        *why = "cylinder with zero length or radius";
        return nullptr;
    }
    *frame = axis_frame(s.base, axis);
    double r = std::fabs(s.radius);
    return std::make_unique<ConePrim>(r, r, s.open);
}

std::unique_ptr<Primitive> make_cone(const scene::Cone& s, Transform* frame, const char** why) {
    Vec3 axis = s.cap - s.base;
    double r0 = std::fabs(s.base_radius), r1 = std::fabs(s.cap_radius);
    if (!is_finite(s.base) || !is_finite(s.cap) || !std::isfinite(r0) || !std::isfinite(r1) ||
        !(length_squared(axis) > 0) || !(r0 > 0 || r1 > 0)) {
        *why = "cone with zero length or both radii zero";
        return nullptr;
    }
    *frame = axis_frame(s.base, axis);
    return std::make_unique<ConePrim>(r0, r1, s.open);
}

}  // namespace glint::render
