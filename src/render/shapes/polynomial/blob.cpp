// blob (POV-Ray 3.7 manual 2.4.1.1; blob.cpp): a field summed over components, each
// strength * (1 - r^2/radius^2)^2 = c0 r^4 + c1 r^2 + c2 inside its radius, r measured in the
// component's own space; the surface is where the sum equals the threshold. A cylinder
// component is three elements, as in POV-Ray: the field of the distance to the axis between
// the end planes, and a hemisphere at each end. Along a ray every element's field is a quartic
// in t inside the element's chord, so between consecutive chord ends the sum is one quartic,
// solved on that stretch. The normal is minus the field's gradient. Components with textures of
// their own blend them at a hit by the size of each element's field there (Determine_Textures).
// Blobs of many components (molecules) keep a bounding volume hierarchy over the elements, as
// POV-Ray keeps a sphere tree (Build_Blob_Hierarchy): rays and points then meet only the
// elements whose bounds they reach, instead of every element. Stretches whose quartic keeps
// clear of zero by its Bernstein coefficients are not solved (POV-Ray's test too).
#include "render/shapes/polynomial/blob.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "render/accel/bvh.h"
#include "render/shapes/polynomial/poly_solve.h"
#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

enum class Kind { Sphere, Cylinder, BaseCap, ApexCap };

struct Element {
    Kind kind = Kind::Sphere;
    bool identity = true;
    Transform xf;       // element space -> blob space
    Vec3 o;             // sphere centre (element space)
    double len = 0;     // cylinder length along element z
    double rad2 = 1;
    double c0 = 0, c1 = 0, c2 = 0;
    int material = -1;  // the component's texture (Scene::materials id), -1: the blob's

    Vec3 to_local(const Vec3& p) const { return identity ? p : xf.inverse_point(p); }
    Vec3 dir_local(const Vec3& d) const { return identity ? d : xf.inverse_vector(d); }
    // The element's field at blob-space point p, and whether p is in its range.
    bool field_at(const Vec3& p, double* f) const {
        Vec3 v;
        if (!radial(to_local(p), &v)) return false;
        const double r2 = length_squared(v);
        *f = r2 * (r2 * c0 + c1) + c2;
        return true;
    }
    // The vector whose squared length is r^2 (element space), and whether p is in range.
    bool radial(const Vec3& pl, Vec3* v) const {
        switch (kind) {
            case Kind::Sphere: *v = pl - o; return length_squared(*v) < rad2;
            case Kind::BaseCap: *v = pl; return pl.z <= 0 && length_squared(*v) <= rad2;
            case Kind::ApexCap:
                *v = Vec3(pl.x, pl.y, pl.z - len);
                return v->z >= 0 && length_squared(*v) <= rad2;
            case Kind::Cylinder:
                *v = Vec3(pl.x, pl.y, 0);
                return pl.z >= 0 && pl.z <= len && length_squared(*v) <= rad2;
        }
        return false;
    }
};

struct Event {
    double t;
    int element;
    bool enter;
};

// Below this many elements a plain loop over them all costs less than a hierarchy.
constexpr size_t kHierarchyMin = 8;

// Per-thread scratch lists, kept between queries so that a ray costs no allocations. The point
// queries (field, normal, blend) have their own, as intersect_all() asks for normals while
// its events are live.
struct Scratch {
    std::vector<int> ray_ids, point_ids, active;
    std::vector<Event> events;
};
Scratch& scratch() {
    thread_local Scratch s;
    return s;
}

class BlobPrim final : public Primitive {
public:
    // `element_bounds`: each element's region of influence in blob space. `fast`: queries
    // visit only the elements whose bounds they reach and skip stretches without roots; false:
    // every element, every stretch solved (the plain algorithm, the tests' reference).
    BlobPrim(std::vector<Element> els, const std::vector<Bounds3>& element_bounds,
             double threshold, Bounds3 b, double scale, bool fast)
        : els_(std::move(els)), threshold_(threshold), bounds_(b), scale_(scale), fast_(fast) {
        for (const Element& e : els_) textured_ = textured_ || e.material >= 0;
        // Two elements a leaf: on bench/blob_scene.py's molecules one did as well, four and
        // eight cost 5-20% more.
        if (fast && els_.size() >= kHierarchyMin) bvh_ = Bvh(element_bounds, 2);
        // Elements the hierarchy leaves out (unbounded ones) are met by every query.
        std::vector<bool> held(els_.size(), false);
        for (int i : bvh_.order()) held[i] = true;
        for (size_t i = 0; i < els_.size(); ++i)
            if (!held[i]) loose_.push_back(static_cast<int>(i));
    }

    Bounds3 bounds() const override { return bounds_; }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        // The stretches come nearest first, so the first with a root holds the nearest hit.
        HitList hits;
        trace(ray, tmax, Mode::Nearest, &hits);
        if (hits.empty()) return false;
        const LocalHit* best = &hits[0];
        for (const LocalHit& h : hits)
            if (h.t < best->t) best = &h;
        *hit = *best;
        return true;
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        trace(ray, tmax, Mode::All, hits);
    }

    void intersect_all_points(const Ray& ray, double tmax, HitList* hits) const override {
        trace(ray, tmax, Mode::Points, hits);
    }

    bool inside(const Vec3& p) const override { return field(p) > threshold_ - 1e-6; }

    double field(const Vec3& p) const {
        double sum = 0;
        for (int i : near_point(p)) {
            double f;
            if (els_[i].field_at(p, &f)) sum += f;
        }
        return sum;
    }

    // Every element whose field reaches p, weighted by |field| (negative components count
    // too), the weights normalised to sum to 1 (Determine_Textures).
    bool texture_blend(const Vec3& p, std::vector<TextureWeight>* out) const override {
        out->clear();
        if (!textured_) return false;
        double sum = 0;
        for (int i : near_point(p)) {
            double f;
            if (!els_[i].field_at(p, &f)) continue;
            const double d = std::fabs(f);
            if (!(d > 0)) continue;
            out->push_back({els_[i].material, d});
            sum += d;
        }
        // No element reaching the surface (a threshold <= 0) leaves no texture: POV-Ray
        // shades such a point black.
        for (TextureWeight& w : *out) w.weight /= sum;
        return true;
    }

private:
    // All: every hit with its normal. Points: t and p only (shadow rays through CSG).
    // Nearest: stops after the first stretch with a hit.
    enum class Mode { All, Points, Nearest };

    void trace(const Ray& ray, double tmax, Mode mode, HitList* hits) const {
        double len = length(ray.dir);
        if (!(len > 0)) return;
        Scratch& s = scratch();
        std::vector<Event>& ev = s.events;
        ev.clear();
        // The elements in their own order, so that the events, their sort and so each
        // stretch's sum come out as a loop over all elements would make them.
        for (int i : near_ray(ray)) {
            double a, b;
            if (!chord(els_[i], ray, &a, &b)) continue;
            a = std::max(a, 0.0);
            if (!(b > a)) continue;
            ev.push_back({a, i, true});
            ev.push_back({b, i, false});
        }
        if (ev.empty()) return;
        std::sort(ev.begin(), ev.end(), [](const Event& x, const Event& y) {
            return x.t < y.t || (x.t == y.t && x.enter && !y.enter);
        });
        double tmin = 1e-7 * scale_ / len;
        std::vector<int>& active = s.active;
        active.clear();
        double last_root = -kInfinity;
        for (size_t e = 0; e + 1 < ev.size(); ++e) {
            if (ev[e].enter) {
                active.push_back(ev[e].element);
            } else {
                active.erase(std::find(active.begin(), active.end(), ev[e].element));
            }
            double l = ev[e].t, r = ev[e + 1].t;
            if (active.empty() || !(r > l) || l >= tmax) continue;
            // The summed quartic in u = t - l.
            double c[5] = {-threshold_, 0, 0, 0, 0};
            Vec3 o = ray.origin + ray.dir * l;
            for (int i : active) add_quartic(els_[i], o, ray.dir, c);
            if (fast_ && clear_of_zero(c, r - l)) continue;
            double u[4];
            int n = solve_in_interval(c, 4, 0, r - l, u);
            size_t before = hits->size();
            for (int k = 0; k < n; ++k) {
                double t = l + u[k];
                if (!(t > tmin) || !(t < tmax)) continue;
                if (std::fabs(t - last_root) <= 1e-12 * std::max(1.0, std::fabs(t))) continue;
                last_root = t;
                LocalHit& h = hits->emplace_back();
                h.t = t;
                h.p = ray.origin + ray.dir * t;
                h.p_error = rounding_error(h.p, 8) + Vec3(1e-8 * scale_);
                if (mode == Mode::Points) continue;
                h.ng = normal(h.p);
                h.n = h.ng;
                if (textured_) {
                    h.uv_source = this;
                    h.uv_point = h.p;
                }
            }
            if (mode == Mode::Nearest && hits->size() > before) return;
        }
    }

    // The elements whose bounds the ray reaches at t >= 0 (the chords are clipped there), in
    // ascending order. The list lives until the next call on this thread.
    const std::vector<int>& near_ray(const Ray& ray) const {
        std::vector<int>& ids = scratch().ray_ids;
        ids = loose_;
        if (bvh_.empty()) return ids;
        double tmax = kInfinity;
        bvh_.traverse(ray, tmax, [&](int i, double&) {
            ids.push_back(i);
            return false;
        });
        std::sort(ids.begin(), ids.end());
        return ids;
    }

    // The elements whose bounds hold p, in ascending order; the list lives until the next
    // call on this thread.
    const std::vector<int>& near_point(const Vec3& p) const {
        std::vector<int>& ids = scratch().point_ids;
        ids = loose_;
        if (bvh_.empty()) return ids;
        const std::vector<Bvh::Node>& nodes = bvh_.nodes();
        const std::vector<int>& order = bvh_.order();
        int stack[128];
        int sp = 0, cur = 0;
        for (;;) {
            const Bvh::Node& n = nodes[cur];
            bool in = p.x >= n.box[0][0] && p.x <= n.box[1][0] && p.y >= n.box[0][1] &&
                      p.y <= n.box[1][1] && p.z >= n.box[0][2] && p.z <= n.box[1][2];
            if (in) {
                if (n.count > 0) {
                    for (int k = 0; k < n.count; ++k) ids.push_back(order[n.index + k]);
                } else {
                    stack[sp++] = n.index;
                    cur = cur + 1;
                    continue;
                }
            }
            if (sp == 0) break;
            cur = stack[--sp];
        }
        std::sort(ids.begin(), ids.end());
        return ids;
    }

    Vec3 normal(const Vec3& p) const {
        Vec3 n(0);
        for (int i : near_point(p)) {
            const Element& e = els_[i];
            Vec3 v;
            if (!e.radial(e.to_local(p), &v)) continue;
            double r2 = length_squared(v);
            double w = -2 * e.c0 * r2 - e.c1;
            n += (e.identity ? v : e.xf.normal(v)) * w;
        }
        double l = length(n);
        return l > 0 && std::isfinite(l) ? n / l : Vec3(0, 1, 0);
    }

    // Whether the quartic c (ascending) has no root in [0, w] for certain. On [0, w] it lies in
    // the convex hull of its Bernstein coefficients, so if they all keep one sign it has no
    // root there. The margin, far above the coefficients' rounding, leaves every stretch that
    // could hold a root to the solver, so skipping never changes the roots found.
    static bool clear_of_zero(const double c[5], double w) {
        double a[5], wi = 1, mag = 0;
        for (int i = 0; i < 5; ++i) {
            a[i] = c[i] * wi;
            wi *= w;
            mag += std::fabs(a[i]);
        }
        double b[5] = {a[0], a[0] + a[1] / 4, a[0] + a[1] / 2 + a[2] / 6,
                       a[0] + 0.75 * a[1] + a[2] / 2 + a[3] / 4, a[0] + a[1] + a[2] + a[3] + a[4]};
        double m = 1e-10 * mag;
        bool above = true, below = true;
        for (double x : b) {
            above = above && x > m;
            below = below && x < -m;
        }
        return above || below;
    }

    // Adds the element's field along o + u d as a quartic in u (ascending coefficients).
    static void add_quartic(const Element& e, const Vec3& o, const Vec3& d, double c[5]) {
        Vec3 po = e.to_local(o), dd = e.dir_local(d);
        double t0, t1, t2;
        if (e.kind == Kind::Cylinder) {
            t0 = po.x * po.x + po.y * po.y;
            t1 = po.x * dd.x + po.y * dd.y;
            t2 = dd.x * dd.x + dd.y * dd.y;
        } else {
            Vec3 v = e.kind == Kind::Sphere ? po - e.o
                     : e.kind == Kind::ApexCap ? Vec3(po.x, po.y, po.z - e.len)
                                               : po;
            t0 = dot(v, v);
            t1 = dot(v, dd);
            t2 = dot(dd, dd);
        }
        // r^2(u) = t0 + 2 t1 u + t2 u^2; field = c0 r^4 + c1 r^2 + c2.
        c[4] += e.c0 * t2 * t2;
        c[3] += 4 * e.c0 * t1 * t2;
        c[2] += 2 * e.c0 * (2 * t1 * t1 + t0 * t2) + e.c1 * t2;
        c[1] += 2 * t1 * (2 * e.c0 * t0 + e.c1);
        c[0] += t0 * (e.c0 * t0 + e.c1) + e.c2;
    }

    // Where the ray is inside the element's region of influence, in ray parameters.
    static bool chord(const Element& e, const Ray& ray, double* tmin, double* tmax) {
        Vec3 p = e.to_local(ray.origin), d = e.dir_local(ray.dir);
        auto sphere = [&](const Vec3& c, double* a, double* b) {
            Vec3 v = p - c;
            double dd = dot(d, d), bh = dot(v, d);
            Vec3 perp = v - d * (bh / dd);
            double disc = dd * (e.rad2 - length_squared(perp));
            if (!(disc > 0)) return false;
            double s = std::sqrt(disc);
            *a = (-bh - s) / dd;
            *b = (-bh + s) / dd;
            return true;
        };
        switch (e.kind) {
            case Kind::Sphere: return sphere(e.o, tmin, tmax);
            case Kind::BaseCap:
            case Kind::ApexCap: {
                bool apex = e.kind == Kind::ApexCap;
                Vec3 c(0, 0, apex ? e.len : 0);
                if (!sphere(c, tmin, tmax)) return false;
                // Keep the part on the cap's side of its plane.
                double z1 = p.z + *tmin * d.z - c.z, z2 = p.z + *tmax * d.z - c.z;
                bool in1 = apex ? z1 >= 0 : z1 <= 0, in2 = apex ? z2 >= 0 : z2 <= 0;
                if (!in1 && !in2) return false;
                if (in1 && in2) return true;
                double t = (c.z - p.z) / d.z;
                if (in1) *tmax = t;
                else *tmin = t;
                return *tmax > *tmin;
            }
            case Kind::Cylinder: {
                double lo = kInfinity, hi = -kInfinity;
                auto take = [&](double t) {
                    lo = std::min(lo, t);
                    hi = std::max(hi, t);
                };
                double a = d.x * d.x + d.y * d.y;
                if (a > 0) {
                    double bh = p.x * d.x + p.y * d.y;
                    double c = p.x * p.x + p.y * p.y - e.rad2;
                    double disc = bh * bh - a * c;
                    if (disc > 0) {
                        double s = std::sqrt(disc);
                        for (double t : {(-bh - s) / a, (-bh + s) / a}) {
                            double z = p.z + t * d.z;
                            if (z >= 0 && z <= e.len) take(t);
                        }
                    }
                }
                if (d.z != 0) {
                    for (double z : {0.0, e.len}) {
                        double t = (z - p.z) / d.z;
                        double x = p.x + t * d.x, y = p.y + t * d.y;
                        if (x * x + y * y <= e.rad2) take(t);
                    }
                }
                *tmin = lo;
                *tmax = hi;
                return hi > lo;
            }
        }
        return false;
    }

    std::vector<Element> els_;
    Bvh bvh_;                 // over the elements' bounds; empty for few elements
    std::vector<int> loose_;  // elements outside bvh_, ascending
    double threshold_;
    Bounds3 bounds_;
    double scale_;
    bool fast_;
    bool textured_ = false;  // some component has a texture of its own
};

std::unique_ptr<Primitive> build_blob(const scene::Blob& s, const char** why, bool fast) {
    std::vector<Element> els;
    std::vector<Bounds3> el_bounds;
    // An element's region in blob space, widened by far more than the rounding of its chord
    // and radial tests, so that culling by these bounds never drops an element that counts.
    auto add = [&](const Element& e, const Bounds3& local) {
        Bounds3 w = e.identity ? local : e.xf.bounds(local);
        double m = std::max({max_component(abs(w.lo)), max_component(abs(w.hi)), 1e-300});
        w.lo -= Vec3(1e-7 * m);
        w.hi += Vec3(1e-7 * m);
        els.push_back(e);
        el_bounds.push_back(w);
    };
    Bounds3 b;
    for (const scene::BlobComponent& c : s.components) {
        double rad2 = c.radius * c.radius;
        if (!(rad2 > 0)) continue;
        Element e;
        e.rad2 = rad2;
        e.c0 = c.strength / (rad2 * rad2);
        e.c1 = -2 * c.strength / rad2;
        e.c2 = c.strength;
        e.material = c.material;
        Bounds3 local;
        if (!c.cylinder) {
            e.kind = Kind::Sphere;
            e.o = c.center;
            e.xf = c.transform;
            e.identity = c.transform.is_identity();
            local = {c.center - Vec3(c.radius), c.center + Vec3(c.radius)};
            if (c.strength > 0) b.extend(e.identity ? local : e.xf.bounds(local));
            add(e, local);
            continue;
        }
        Vec3 axis = c.apex - c.center;
        double len = length(axis);
        if (!(len > 1e-10)) continue;
        e.xf = axis_frame(c.center, axis / len).then(c.transform);
        e.identity = false;
        e.len = len;
        local = {Vec3(-c.radius, -c.radius, -c.radius), Vec3(c.radius, c.radius, len + c.radius)};
        if (c.strength > 0) b.extend(e.xf.bounds(local));
        // Each part bounded on its own: the body between the end planes, a cap beyond its end.
        const Vec3 side(c.radius, c.radius, 0);
        e.kind = Kind::Cylinder;
        add(e, {-side, side + Vec3(0, 0, len)});
        e.kind = Kind::BaseCap;
        add(e, {-side - Vec3(0, 0, c.radius), side});
        e.kind = Kind::ApexCap;
        add(e, {-side + Vec3(0, 0, len), side + Vec3(0, 0, len + c.radius)});
    }
    if (els.empty() || b.empty()) {
        *why = "blob without components of positive strength and radius";
        return nullptr;
    }
    double scale = std::max({length(b.lo), length(b.hi), 1e-300});
    Vec3 pad = Vec3(1e-9 * scale);
    b.lo -= pad;
    b.hi += pad;
    return std::make_unique<BlobPrim>(std::move(els), el_bounds, s.threshold, b, scale,
                                      fast);
}

}  // namespace

std::unique_ptr<Primitive> make_blob(const scene::Blob& s, const char** why) {
    return build_blob(s, why, true);
}

std::unique_ptr<Primitive> make_blob_exhaustive(const scene::Blob& s, const char** why) {
    return build_blob(s, why, false);
}

}  // namespace glint::render
