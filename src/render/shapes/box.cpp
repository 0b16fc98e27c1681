// Axis-aligned box (POV-Ray 3.7 manual 2.4.1.2) between two corners, by slabs (Kay and Kajiya
// 1986). Direction components that are exactly zero are handled by branching, never by
// 0 * inf, so rays along faces and edges give no NaN. The hit coordinate on the face axis is
// the face itself, so hit points sit exactly on the box.
#include <cmath>

#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

class BoxPrim final : public Primitive {
public:
    explicit BoxPrim(const scene::Box& s)
        : lo_(min(s.corner1, s.corner2)), hi_(max(s.corner1, s.corner2)) {}

    Bounds3 bounds() const override { return {lo_, hi_}; }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        Slab s;
        if (!slabs(ray, &s)) return false;
        if (s.t0 > 0 && s.t0 < tmax) {
            fill(ray, s.t0, s.axis0, s.side0, hit);
            return true;
        }
        if (s.t1 > 0 && s.t1 < tmax) {
            fill(ray, s.t1, s.axis1, s.side1, hit);
            return true;
        }
        return false;
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        Slab s;
        if (!slabs(ray, &s)) return;
        if (s.t0 > 0 && s.t0 < tmax) fill(ray, s.t0, s.axis0, s.side0, &hits->emplace_back());
        if (s.t1 > 0 && s.t1 < tmax) fill(ray, s.t1, s.axis1, s.side1, &hits->emplace_back());
    }

    void intersect_all_points(const Ray& ray, double tmax, HitList* hits) const override {
        Slab s;
        if (!slabs(ray, &s)) return;
        if (s.t0 > 0 && s.t0 < tmax) fill_point(ray, s.t0, s.axis0, s.side0, &hits->emplace_back());
        if (s.t1 > 0 && s.t1 < tmax) fill_point(ray, s.t1, s.axis1, s.side1, &hits->emplace_back());
    }

    bool inside(const Vec3& p) const override {
        return p.x >= lo_.x && p.x <= hi_.x && p.y >= lo_.y && p.y <= hi_.y && p.z >= lo_.z &&
               p.z <= hi_.z;
    }

private:
    struct Slab {
        double t0 = -kInfinity, t1 = kInfinity;
        int axis0 = -1, axis1 = -1;
        int side0 = 0, side1 = 0;  // 0: the lo face, 1: the hi face
    };

    bool slabs(const Ray& ray, Slab* s) const {
        for (int i = 0; i < 3; ++i) {
            double o = ray.origin[i], d = ray.dir[i];
            if (d == 0) {
                if (o < lo_[i] || o > hi_[i] || std::isnan(o)) return false;
                continue;
            }
            double ta = (lo_[i] - o) / d, tb = (hi_[i] - o) / d;
            int sa = 0, sb = 1;
            // By the direction's sign, not by comparing ta and tb: on a flat box (lo == hi)
            // they are equal and the ray still enters by the face it comes from, as POV-Ray's
            // Intersect_Box has it (a refracting sheet is entered, not left).
            if (d < 0) {
                std::swap(ta, tb);
                std::swap(sa, sb);
            }
            if (ta > s->t0) {
                s->t0 = ta;
                s->axis0 = i;
                s->side0 = sa;
            }
            if (tb < s->t1) {
                s->t1 = tb;
                s->axis1 = i;
                s->side1 = sb;
            }
        }
        // A ray with no constraining axis (zero direction) cannot hit anything.
        return s->axis0 >= 0 && s->axis1 >= 0 && s->t0 <= s->t1;
    }

    void fill_point(const Ray& ray, double t, int axis, int side, LocalHit* h) const {
        Vec3 p = ray.origin + ray.dir * t;
        p = min(max(p, lo_), hi_);
        p[axis] = side ? hi_[axis] : lo_[axis];
        h->t = t;
        h->p = p;
    }

    void fill(const Ray& ray, double t, int axis, int side, LocalHit* h) const {
        fill_point(ray, t, axis, side, h);
        const Vec3& p = h->p;
        h->p_error = rounding_error(p, 1);
        Vec3 n(0, 0, 0);
        n[axis] = side ? 1 : -1;
        h->ng = n;
        h->n = n;
        h->uv = uv(p, axis, side);
        h->has_uv = true;
    }

    // POV-Ray's box uv_mapping (boxes.cpp, Box::UVCoord): a cube-map cross laid out in a
    // 4 x 3 grid of the unit square.
    Vec2 uv(const Vec3& p, int axis, int side) const {
        Vec3 q = p - lo_, ext = hi_ - lo_;
        for (int i = 0; i < 3; ++i) q[i] = ext[i] > 0 ? q[i] / ext[i] : 0;  // flat boxes
        switch (axis * 2 + side) {
            case 0: return {q.z / 4.0, 1.0 / 3.0 + q.y / 3.0};
            case 1: return {0.75 - q.z / 4.0, 1.0 / 3.0 + q.y / 3.0};
            case 2: return {0.25 + q.x / 4.0, q.z / 3.0};
            case 3: return {0.25 + q.x / 4.0, 1.0 - q.z / 3.0};
            case 4: return {1.0 - q.x / 4.0, 1.0 / 3.0 + q.y / 3.0};
            default: return {0.25 + q.x / 4.0, 1.0 / 3.0 + q.y / 3.0};
        }
    }

    Vec3 lo_, hi_;
};

}  // namespace

std::unique_ptr<Primitive> make_box(const scene::Box& s) { return std::make_unique<BoxPrim>(s); }

}  // namespace glint::render
