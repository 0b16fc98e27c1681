// polygon (POV-Ray 3.7 manual 2.4.2.3; polygon.cpp): coplanar points projected onto a frame of
// their plane; a point is on the polygon by the even-odd crossing rule, where a vertex equal to
// the first vertex of its sub-polygon closes it and the next vertex starts another one.
// Like POV-Ray, a polygon has no inside.
#include <cmath>
#include <vector>

#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

class PolygonPrim final : public Primitive {
public:
    PolygonPrim(Vec3 o, Vec3 u, Vec3 v, Vec3 w, std::vector<Vec2> pts, Bounds3 b)
        : o_(o), u_(u), v_(v), w_(w), pts_(std::move(pts)), bounds_(b) {}

    Bounds3 bounds() const override { return bounds_; }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        double dn = dot(ray.dir, w_);
        if (dn == 0) return false;
        Vec3 rel = o_ - ray.origin;
        double num = dot(rel, w_);
        // The signed distance of the origin to the plane is known to within its rounding.
        if (std::fabs(num) <= gamma(6) * (length(o_) + length(ray.origin))) return false;
        double t = num / dn;
        if (!(t > 0) || !(t < tmax)) return false;
        Vec3 p = ray.origin + ray.dir * t;
        Vec3 q = p - o_;
        if (!in_polygon(dot(q, u_), dot(q, v_))) return false;
        hit->t = t;
        hit->p = p;
        hit->p_error = rounding_error(p, 6) + rounding_error(o_, 6);
        hit->ng = w_;
        hit->n = w_;
        return true;
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        LocalHit h;
        if (intersect(ray, tmax, &h)) hits->push_back(h);
    }

    bool inside(const Vec3&) const override { return false; }

    // The crossing test of POV-Ray's in_polygon (after Haines, "Point in Polygon Strategies").
    bool in_polygon(double tx, double ty) const {
        const size_t n = pts_.size();
        const Vec2* v0 = &pts_[0];
        const Vec2* v1 = &pts_[1];
        const Vec2* first = v0;
        bool y0 = v0->y >= ty;
        bool in = false;
        for (size_t i = 1; i < n;) {
            bool y1 = v1->y >= ty;
            if (y0 != y1 &&
                (((v1->y - ty) * (v0->x - v1->x) >= (v1->x - tx) * (v0->y - v1->y)) == y1))
                in = !in;
            if (i + 2 < n && v1->x == first->x && v1->y == first->y) {
                v0 = &pts_[++i];
                if (i + 1 >= n) break;
                v1 = &pts_[++i];
                y0 = v0->y >= ty;
                first = v0;
            } else {
                v0 = v1;
                if (i + 1 >= n) break;
                v1 = &pts_[++i];
                y0 = y1;
            }
        }
        return in;
    }

private:
    Vec3 o_, u_, v_, w_;
    std::vector<Vec2> pts_;
    Bounds3 bounds_;
};

}  // namespace

std::unique_ptr<Primitive> make_polygon(const scene::Polygon& s, const char** why) {
    const auto& p = s.points;
    const double kEps = 1e-10;  // POV-Ray's EPSILON for these tests
    if (p.size() < 3) {
        *why = "polygon with fewer than 3 points";
        return nullptr;
    }
    Vec3 o = p[0], u, v, w;
    size_t i = 1;
    for (; i < p.size(); ++i) {
        u = p[i] - o;
        if (length_squared(u) > kEps) break;
    }
    for (++i; i < p.size(); ++i) {
        v = p[i] - o;
        w = cross(u, v);
        if (length_squared(v) > kEps && length_squared(w) > kEps) break;
    }
    if (i >= p.size()) {
        *why = "polygon whose points are collinear";
        return nullptr;
    }
    u = normalize(cross(v, w));
    v = normalize(cross(w, u));
    w = normalize(w);
    std::vector<Vec2> pts;
    Bounds3 b;
    double scale = 0;
    for (const Vec3& q : p) scale = std::max(scale, length(q - o));
    for (const Vec3& q : p) {
        Vec3 r = q - o;
        if (std::fabs(dot(r, w)) > 1e-10 * std::max(1.0, scale)) {
            *why = "polygon whose points are not coplanar";
            return nullptr;
        }
        pts.push_back({dot(r, u), dot(r, v)});
        b.extend(q);
    }
    Vec3 pad = rounding_error(abs(b.lo) + abs(b.hi), 4) + Vec3(1e-9 * scale);
    b.lo -= pad;
    b.hi += pad;
    return std::make_unique<PolygonPrim>(o, u, v, w, std::move(pts), b);
}

}  // namespace glint::render
