// isosurface (POV-Ray 3.7 manual 2.4.2.3): the zero set of f(p) - threshold inside a box or
// sphere container, found the way POV-Ray's isosurf.cpp (R. Suzuki's "method 2") finds it, so
// that the same max_gradient leaves the same holes: the interval the container cuts from the
// ray is halved while f1 + f2 < max_gradient * length (a root may lie between), down to
// `accuracy`, and the hit is the far end of the first such interval where f < 0. A closed
// container shows its own surface where it cuts the inside (f < 0). POV-Ray's per-thread cache
// of the last failed interval and its carrying an adapted max_gradient (evaluate) from ray to
// ray are left out: both make a pixel depend on the pixels traced before it.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "render/shapes/container.h"
#include "render/shapes/shapes.h"
#include "render/textures/pattern.h"
#include "scene/scene.h"

namespace glint::render {
namespace {

constexpr double kEpsilon = 1e-10;        // POV-Ray's EPSILON
constexpr double kBoundHuge = 2e10;       // BOUND_HUGE
constexpr int kMaxHits = 12;              // max_trace (at most 10) + the container's two

struct Sample {
    double t, f;
};

class IsosurfacePrim final : public Primitive {
public:
    IsosurfacePrim(const scene::Isosurface& s, const scene::Scene& scene)
        : s_(s), functions_(scene.functions) {
        ctx_.noise_generator = scene.global.noise_generator;
        ctx_.number_of_waves = scene.global.number_of_waves;
        ctx_.functions = &functions_;
        env_ = user_function_env(ctx_);
    }
    IsosurfacePrim(const IsosurfacePrim&) = delete;
    IsosurfacePrim& operator=(const IsosurfacePrim&) = delete;

    Bounds3 bounds() const override { return container_bounds(s_.container); }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        Found found[kMaxHits];
        const int n = trace(ray, found);
        const Found* best = nullptr;
        for (int i = 0; i < n; ++i)
            if (found[i].t > 0 && found[i].t < tmax && (!best || found[i].t < best->t))
                best = &found[i];
        if (!best) return false;
        fill(ray, *best, hit);
        return true;
    }

    bool occludes(const Ray& ray, double tmax) const override {
        Found found[kMaxHits];
        const int n = trace(ray, found);
        for (int i = 0; i < n; ++i)
            if (found[i].t > 0 && found[i].t < tmax) return true;
        return false;
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        Found found[kMaxHits];
        const int n = trace(ray, found);
        for (int i = 0; i < n; ++i)
            if (found[i].t > 0 && found[i].t < tmax) fill(ray, found[i], &hits->emplace_back());
    }

    void intersect_all_points(const Ray& ray, double tmax, HitList* hits) const override {
        Found found[kMaxHits];
        const int n = trace(ray, found);
        for (int i = 0; i < n; ++i) {
            if (!(found[i].t > 0 && found[i].t < tmax)) continue;
            LocalHit& h = hits->emplace_back();
            h.t = found[i].t;
            h.p = ray.origin + ray.dir * found[i].t;
        }
    }

    // POV-Ray's IsoSurface::Inside: in the container (faces included) and f <= threshold.
    bool inside(const Vec3& p) const override {
        const scene::Container& c = s_.container;
        if (c.sphere) {
            if (length_squared(c.center - p) > c.radius * c.radius) return false;
        } else {
            for (int i = 0; i < 3; ++i)
                if (p[i] < c.corner1[i] || p[i] > c.corner2[i]) return false;
        }
        return !(value(p) > 0);
    }

    void gradient_notes(std::vector<GradientNote>* out) const override {
        out->push_back({s_.function, gradient_.load(std::memory_order_relaxed), s_.max_gradient,
                        s_.evaluate});
    }

private:
    // A hit: its t and, for one on the container, the face (1..6: -x, +x, -y, +y, -z, +z).
    struct Found {
        double t = 0;
        int side = 0;
    };
    // The state of one ray's search (POV-Ray's ISO_ThreadData, without the cache); d is unit.
    struct Search {
        Vec3 o, d;
        double sign = 1;      // -1 while looking for the way out (the ray is inside)
        double maxg = 1;      // max_gradient, adapted per ray under `evaluate`
        double t_root = 0;
        double gradient = 0;  // the steepest f met along the ray
    };

    double raw(const Vec3& p) const {
        const double args[3] = {p.x, p.y, p.z};
        return scene::evaluate_function(env_, s_.function, args, 3);
    }
    double value(const Vec3& p) const { return raw(p) - s_.threshold; }
    double along(const Search& sr, double t) const {
        return sr.sign * value(sr.o + sr.d * t);
    }

    // Box::Intersect / Sphere::Intersect as the isosurface uses them (a unit direction).
    bool container(const Ray& ray, double* t1, double* t2, int* side1, int* side2) const {
        return container_interval(s_.container, ray.origin, ray.dir, t1, t2, side1, side2);
    }

    // IsoSurface::All_Intersections: up to max_trace roots (and the container's own surface
    // unless open) in the order POV-Ray pushes them; returns how many.
    int trace(const Ray& ray, Found* out) const {
        const double len = length(ray.dir);
        if (!(len > 0) || !std::isfinite(len)) return 0;
        Ray unit = ray;
        unit.dir = ray.dir / len;
        const int n = trace_unit(unit, out);
        for (int i = 0; i < n; ++i) out[i].t /= len;
        return n;
    }

    // trace() along a unit direction: t, accuracy and the steps are distances in object space.
    // (POV-Ray measures them in world space along its unit world rays; glint's shadow rays are
    // not unit length, and an object-space measure keeps them consistent with camera rays. Only
    // a scaled isosurface sees a difference: its accuracy scales with it.)
    int trace_unit(const Ray& ray, Found* out) const {
        double d1 = 0, d2 = 0;
        int side1 = 0, side2 = 0;
        if (!container(ray, &d1, &d2, &side1, &side2)) return 0;
        if (d1 < 0) d1 = 0;
        const double acc = s_.accuracy;
        Search sr;
        sr.o = ray.origin;
        sr.d = ray.dir;
        sr.maxg = s_.max_gradient;
        const double near_surface = sr.maxg * acc * 4.0;
        int n = 0, itrace = 0;
        if (!s_.open) {
            const double f1 = value(sr.o + sr.d * d1);
            if (d1 > acc) {
                if (f1 < 0) {  // the container cuts the inside: its face is the surface
                    out[n++] = {d1, side1};
                    ++itrace;
                    sr.sign = -1;
                }
            } else {
                // The ray starts in the container: on the surface, step off it to see which way
                // it goes.
                if (f1 < near_surface) {
                    d1 = acc * 5.0;
                    if (value(sr.o + sr.d * d1) < 0) sr.sign = -1;
                }
                if (value(sr.o + sr.d * d2) < 0) out[n++] = {d2, side2};
            }
        }
        double tmax = std::min(d2, kBoundHuge);
        double tmin = std::min(d2, d1);
        if (tmax - tmin < acc) return n > 0 ? n - 1 : 0;
        if (d1 < acc && sr.sign == 1) {
            if (std::fabs(value(sr.o + sr.d * tmin)) < near_surface) {
                tmin = acc * 5.0;
                if (value(sr.o + sr.d * tmin) < 0) sr.sign = -1;
            }
        }
        for (; itrace < s_.max_trace; ++itrace) {
            if (!find_root(sr, &tmin, tmax)) break;
            out[n++] = {tmin, 0};
            tmin += acc * 5.0;
            if (tmax - tmin < acc) break;
            sr.sign = -sr.sign;
        }
        note_gradient(sr.gradient);
        return n;
    }

    // IsoSurface::Function_Find_Root.
    bool find_root(Search& sr, double* t1, double t2) const {
        Sample a{*t1, along(sr, *t1)};
        if (s_.open && a.f < 0) {  // no container surface: the inside may be where we start
            sr.sign = -sr.sign;
            a.f = -a.f;
        }
        const Sample b{t2, along(sr, t2)};
        const double old_maxg = sr.maxg;
        const double t21 = t2 - *t1;
        if (s_.evaluate && old_maxg > s_.eval[0]) sr.maxg = old_maxg * s_.eval[2];
        if (!root_in(sr, a, b, sr.maxg * t21, t21, 1.0 / t21)) return false;
        *t1 = sr.t_root;
        return true;
    }

    // IsoSurface::Function_Find_Root_R: `dt` bounds how far f can fall over [a, b] (the
    // gradient bound times its length), `inv_len` converts a difference of f to a gradient.
    bool root_in(Search& sr, const Sample& a, const Sample& b, double dt, double t21,
                 double inv_len) const {
        const double slope = std::fabs((b.f - a.f) * inv_len);
        if (slope > sr.gradient) sr.gradient = slope;
        if (s_.evaluate && sr.maxg < slope * s_.eval[1]) {
            sr.maxg = slope * s_.eval[1] * s_.eval[1];
            dt = sr.maxg * t21;
        }
        if (t21 < s_.accuracy) {
            if (b.f < 0) {
                sr.t_root = b.t;
                return true;
            }
            return false;
        }
        if (!(a.f + b.f - dt < 0)) return false;
        t21 *= 0.5;
        dt *= 0.5;
        const Sample mid{a.t + t21, along(sr, a.t + t21)};
        return root_in(sr, a, mid, dt, t21, inv_len * 2.0) ||
               root_in(sr, mid, b, dt, t21, inv_len * 2.0);
    }

    void note_gradient(double g) const {
        double seen = gradient_.load(std::memory_order_relaxed);
        while (g > seen && !gradient_.compare_exchange_weak(seen, g, std::memory_order_relaxed)) {
        }
    }

    // IsoSurface::Normal: a container face's own normal, else the forward-difference gradient
    // with step `accuracy`.
    Vec3 normal_at(const Vec3& p, int side) const {
        if (side > 0) {
            Vec3 n(0, 0, 0);
            n[(side - 1) / 2] = (side % 2 == 1) ? -1 : 1;
            return n;
        }
        if (const scene::Container& c = s_.container; c.sphere) {
            const Vec3 r = p - c.center;
            if (std::fabs(length(r) - c.radius) < kEpsilon) return r / c.radius;
        }
        const double f0 = raw(p), h = s_.accuracy;
        Vec3 g(raw(p + Vec3(h, 0, 0)) - f0, raw(p + Vec3(0, h, 0)) - f0,
               raw(p + Vec3(0, 0, h)) - f0);
        if (!is_finite(g) || (g.x == 0 && g.y == 0 && g.z == 0)) g = Vec3(1, 0, 0);
        return normalize(g);
    }

    void fill(const Ray& ray, const Found& f, LocalHit* h) const {
        h->t = f.t;
        h->p = ray.origin + ray.dir * f.t;
        h->p_error = rounding_error(h->p, 4);
        h->ng = normal_at(h->p, f.side);
        h->n = h->ng;
    }

    scene::Isosurface s_;
    // The scene's functions, copied: the function may call others, and the primitive must not
    // depend on the scene's lifetime (geometry is also built from one-object copies).
    std::vector<scene::Function> functions_;
    PatternContext ctx_;
    scene::FunctionEnv env_;
    mutable std::atomic<double> gradient_{0};
};

}  // namespace

void report_gradients(const std::vector<GradientNote>& notes, const scene::Scene& scene,
                      Diagnostics& diag) {
    // Copies of one isosurface are reported once, with the steepest gradient any of them met
    // (POV-Ray's shared ISO_Max_Gradient). Under `evaluate` POV-Ray reports its adapted
    // gradients, which glint does not keep from ray to ray: nothing is said.
    std::map<int, GradientNote> by_function;
    for (const GradientNote& n : notes) {
        if (n.evaluate) continue;
        auto [it, fresh] = by_function.try_emplace(n.function, n);
        if (fresh) continue;
        it->second.found = std::max(it->second.found, n.found);
        it->second.given = std::max(it->second.given, n.given);
    }
    for (const auto& [fn, n] : by_function) {
        if (!(n.found > kEpsilon) || !(n.given > kEpsilon)) continue;
        // POV-Ray's thresholds (IsoSurface::DispatchShutdownMessages).
        const double diff = n.given - n.found, prop = std::fabs(n.given / n.found);
        char numbers[96];
        std::snprintf(numbers, sizeof numbers, "found a gradient of %.3f where max_gradient is %.3f",
                      n.found, n.given);
        const FileLoc& at = scene.functions.at(static_cast<size_t>(fn)).loc;
        if ((prop <= 0.9 && diff <= -0.5) || ((prop <= 0.95 || diff <= -0.1) && n.given < 10.0))
            diag.warning(at, std::string("isosurface ") + numbers +
                                 ": it may have holes; raise max_gradient");
        else if (diff >= 10.0 || (prop >= 1.1 && diff >= 0.5))
            diag.warning(at, std::string("isosurface ") + numbers +
                                 ": a lower max_gradient would render it faster");
    }
}

std::unique_ptr<Primitive> make_isosurface(const scene::Isosurface& s, const scene::Scene& scene,
                                           const char** why) {
    if (s.function < 0 || s.function >= static_cast<int>(scene.functions.size())) {
        *why = "isosurface without a function";
        return nullptr;
    }
    if (scene.functions[s.function].is_vector()) {
        *why = "isosurface of a vector (pigment, transform or spline) function";
        return nullptr;
    }
    if (!s.container.valid()) {
        *why = "isosurface with an empty container";
        return nullptr;
    }
    return std::make_unique<IsosurfacePrim>(s, scene);
}

}  // namespace glint::render
