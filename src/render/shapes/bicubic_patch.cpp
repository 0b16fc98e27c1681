// bicubic_patch (POV-Ray 3.7 manual 2.4.3.1; bezier.cpp). The patch is halved by de Casteljau
// along u and v until a piece is flat enough or u_steps / v_steps halvings are done; each
// piece is the two triangles of its corners, bounded by a sphere about its control points,
// and a hit takes the patch's own normals at the triangle's corners, interpolated.
// POV-Ray measures flatness (the control points' largest distance from the plane of three
// corners) in world space, as it moves the control points with every transform, so the
// factory takes the object's transform and bakes it in.
#include <algorithm>
#include <cmath>
#include <vector>

#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

constexpr double kBezierEpsilon = 1e-10;
constexpr double kBezierTolerance = 1e-5;  // nearest depth, world units
constexpr double kEpsilon = 1e-10;

using Patch = Vec3[4][4];

// Position-free normal of the patch at (u, v): the cross product of its tangents.
Vec3 patch_normal(const Patch& cp, double u0, double v0) {
    static constexpr double kC[] = {1.0, 3.0, 3.0, 1.0};
    double u[4], uu[4], v[4], vv[4], du[4], duu[4], dv[4], dvv[4];
    u[0] = uu[0] = v[0] = vv[0] = 1.0;
    du[0] = duu[0] = dv[0] = dvv[0] = 0.0;
    for (int i = 1; i < 4; ++i) {
        u[i] = u[i - 1] * u0;
        uu[i] = uu[i - 1] * (1.0 - u0);
        v[i] = v[i - 1] * v0;
        vv[i] = vv[i - 1] * (1.0 - v0);
        du[i] = i * u[i - 1];
        duu[i] = -i * uu[i - 1];
        dv[i] = i * v[i - 1];
        dvv[i] = -i * vv[i - 1];
    }
    Vec3 tu(0.0), tv(0.0);
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            const double c = kC[i] * kC[j];
            const double ut = u[i] * uu[3 - i], vt = v[j] * vv[3 - j];
            tu = tu + cp[i][j] * (c * vt * (du[i] * uu[3 - i] + u[i] * duu[3 - i]));
            tv = tv + cp[i][j] * (c * ut * (dv[j] * vv[3 - j] + v[j] * dvv[3 - j]));
        }
    }
    const Vec3 n = cross(tu, tv);
    const double l2 = dot(n, n);
    if (l2 > kBezierEpsilon * dot(tu, tu) * dot(tv, tv)) return n / std::sqrt(l2);
    return {1, 0, 0};
}

// Halves along the first index (u) or the second (v).
void split_u(const Patch& p, Patch& lo, Patch& hi) {
    for (int i = 0; i < 4; ++i) {
        const Vec3 a1 = (p[0][i] + p[1][i]) * 0.5, mid = (p[1][i] + p[2][i]) * 0.5;
        const Vec3 a2 = (a1 + mid) * 0.5, b2 = (p[2][i] + p[3][i]) * 0.5;
        const Vec3 b1 = (mid + b2) * 0.5, m = (a2 + b1) * 0.5;
        const Vec3 l[4] = {p[0][i], a1, a2, m}, h[4] = {m, b1, b2, p[3][i]};
        for (int j = 0; j < 4; ++j) {
            lo[j][i] = l[j];
            hi[j][i] = h[j];
        }
    }
}
void split_v(const Patch& p, Patch& lo, Patch& hi) {
    for (int i = 0; i < 4; ++i) {
        const Vec3 a1 = (p[i][0] + p[i][1]) * 0.5, mid = (p[i][1] + p[i][2]) * 0.5;
        const Vec3 a2 = (a1 + mid) * 0.5, b2 = (p[i][2] + p[i][3]) * 0.5;
        const Vec3 b1 = (mid + b2) * 0.5, m = (a2 + b1) * 0.5;
        const Vec3 l[4] = {p[i][0], a1, a2, m}, h[4] = {m, b1, b2, p[i][3]};
        for (int j = 0; j < 4; ++j) {
            lo[i][j] = l[j];
            hi[i][j] = h[j];
        }
    }
}

// POV-Ray's flatness measure: the control points' largest distance from the plane through
// corners (0,0), (0,3), (3,0) (others where those coincide); negative where there is none.
double flatness_of(const Patch& p) {
    const Vec3 v0 = p[0][0];
    Vec3 v1 = p[0][3], v2;
    if (length(v0 - v1) < kEpsilon) {
        v1 = p[3][3];
        if (length(v0 - v1) < kEpsilon) return -1;
        v2 = p[3][0];
    } else {
        v2 = p[3][0];
    }
    if (length(v1 - v2) < kEpsilon) return -1;
    const Vec3 e1 = v0 - v1, e2 = v2 - v1;
    Vec3 n = cross(e1, e2);
    const double l2 = dot(n, n);
    if (l2 <= kBezierEpsilon * dot(e1, e1) * dot(e2, e2)) return -1;
    n = n / std::sqrt(l2);
    const double d = dot(n, v0);
    const double nl = length(n);
    double dist = 0;
    for (const auto& row : p)
        for (const Vec3& q : row) {
            const double e = nl < kEpsilon ? 0.0 : std::fabs((dot(q, n) - d) / nl);
            dist = std::max(dist, e);
        }
    return dist;
}

struct Node {
    Vec3 center;
    double radius2 = 0;
    int first = -1;  // children: nodes first ... first + count - 1; leaf: index into leaves_
    int count = 0;   // 0: a leaf
};
struct Leaf {
    Vec3 corner[4];  // (u0, v0), (u0, v1), (u1, v1), (u1, v0)
    Vec3 normal[4];
    double u0, u1, v0, v1;
};

class BicubicPatchPrim final : public Primitive {
public:
    explicit BicubicPatchPrim(const scene::BicubicPatch& s, const Transform& xf) : s_(s) {
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) cp_[i][j] = xf.point(s.points[i][j]);
        for (const auto& row : cp_)
            for (const Vec3& q : row) box_.extend(q);
        nodes_.emplace_back();
        build(0, cp_, 0, 1, 0, 1, 0);
    }

    Bounds3 bounds() const override { return box_; }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        return nearest_of_all(ray, tmax, hit);
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        const double len = length(ray.dir);
        if (!(len > 0) || !std::isfinite(len)) return;
        const Vec3 unit = ray.dir / len;
        int stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& n = nodes_[stack[--top]];
            if (!sphere_check(ray.origin, unit, n.center, n.radius2)) continue;
            if (n.count == 0) {
                const Leaf& l = leaves_[n.first];
                triangle(ray, len, tmax, l, 0, 1, 2, hits);
                triangle(ray, len, tmax, l, 0, 2, 3, hits);
                continue;
            }
            for (int c = n.count - 1; c >= 0; --c) stack[top++] = n.first + c;
        }
    }

    bool inside(const Vec3&) const override { return false; }

private:
    void build(int at, const Patch& p, double u0, double u1, double v0, double v1, int depth) {
        Vec3 c(0.0);
        for (const auto& row : p)
            for (const Vec3& q : row) c = c + q;
        c = c / 16.0;
        double r2 = 0;
        for (const auto& row : p)
            for (const Vec3& q : row) r2 = std::max(r2, dot(q - c, q - c));
        nodes_[at].center = c;
        nodes_[at].radius2 = r2;
        const double flat = flatness_of(p);
        const bool split_along_u = depth < s_.u_steps, split_along_v = depth < s_.v_steps;
        if ((flat >= 0 && flat < s_.flatness) || (!split_along_u && !split_along_v)) {
            Leaf l{{p[0][0], p[0][3], p[3][3], p[3][0]}, {}, u0, u1, v0, v1};
            l.normal[0] = patch_normal(cp_, u0, v0);
            l.normal[1] = patch_normal(cp_, u0, v1);
            l.normal[2] = patch_normal(cp_, u1, v1);
            l.normal[3] = patch_normal(cp_, u1, v0);
            nodes_[at].first = static_cast<int>(leaves_.size());
            leaves_.push_back(l);
            return;
        }
        const double um = (u0 + u1) / 2.0, vm = (v0 + v1) / 2.0;
        Patch a, b, c0, c1, c2, c3;
        struct Part {
            const Patch* p;
            double u0, u1, v0, v1;
        };
        Part parts[4];
        int count;
        if (!split_along_u) {
            split_v(p, a, b);
            parts[0] = {&a, u0, u1, v0, vm};
            parts[1] = {&b, u0, u1, vm, v1};
            count = 2;
        } else if (!split_along_v) {
            split_u(p, a, b);
            parts[0] = {&a, u0, um, v0, v1};
            parts[1] = {&b, um, u1, v0, v1};
            count = 2;
        } else {
            split_u(p, a, b);
            split_v(a, c0, c1);
            split_v(b, c2, c3);
            parts[0] = {&c0, u0, um, v0, vm};
            parts[1] = {&c1, u0, um, vm, v1};
            parts[2] = {&c2, um, u1, v0, vm};
            parts[3] = {&c3, um, u1, vm, v1};
            count = 4;
        }
        const int first = static_cast<int>(nodes_.size());
        nodes_[at].first = first;
        nodes_[at].count = count;
        nodes_.resize(nodes_.size() + static_cast<size_t>(count));
        for (int k = 0; k < count; ++k)
            build(first + k, *parts[k].p, parts[k].u0, parts[k].u1, parts[k].v0, parts[k].v1,
                  depth + 1);
    }

    // POV-Ray's test: the ray's line (either direction) passes within the sphere.
    static bool sphere_check(const Vec3& o, const Vec3& unit, const Vec3& c, double r2) {
        const Vec3 oc = c - o;
        const double d1 = dot(oc, oc);
        if (d1 < r2) return true;
        double d2 = dot(oc, unit);
        d2 *= d2;
        return d2 > 0 && d1 - d2 <= r2 + kBezierEpsilon;
    }

    void triangle(const Ray& ray, double len, double tmax, const Leaf& l, int i0, int i1, int i2,
                  HitList* hits) const {
        const Vec3 v0 = l.corner[i0];
        const Vec3 b0 = l.corner[i1] - v0, b1 = l.corner[i2] - v0;
        Vec3 b2 = cross(b0, b1);
        const double d2 = dot(b2, b2);
        if (d2 <= kBezierEpsilon * dot(b1, b1) * dot(b0, b0)) return;
        b2 = b2 / std::sqrt(d2);
        // The dual basis: dot(q, ib[k]) is q's coordinate along b[k].
        const double det = dot(b0, cross(b1, b2));
        if (det == 0 || !std::isfinite(det)) return;
        const Vec3 ib0 = cross(b1, b2) / det, ib1 = cross(b2, b0) / det,
                   ib2 = cross(b0, b1) / det;
        const Vec3 unit = ray.dir / len;
        const double d = dot(unit, ib2);
        if (std::fabs(d) < kBezierEpsilon) return;
        const double depth = dot(v0 - ray.origin, ib2) / d;
        if (depth < kBezierTolerance) return;
        const double t = depth / len;
        if (!(t < tmax)) return;
        const Vec3 p = ray.origin + unit * depth;
        const Vec3 q = p - v0;
        const double a = dot(q, ib0), b = dot(q, ib1);
        if (a < 0.0 || b < 0.0 || a + b > 1.0) return;
        const double r = 1.0 - a - b;
        Vec3 n = l.normal[i0] * r + l.normal[i1] * a + l.normal[i2] * b;
        const double nn = dot(n, n);
        n = nn > kBezierEpsilon ? n / std::sqrt(nn) : Vec3(1, 0, 0);
        const double us[4] = {l.u0, l.u0, l.u1, l.u1}, vs[4] = {l.v0, l.v1, l.v1, l.v0};
        const double u = r * us[i0] + a * us[i1] + b * us[i2];
        const double v = r * vs[i0] + a * vs[i1] + b * vs[i2];
        LocalHit& h = hits->emplace_back();
        h.t = t;
        h.p = p;
        h.p_error = rounding_error(p, 16) + Vec3(1e-9);
        h.n = n;
        h.ng = dot(b2, n) < 0 ? -b2 : b2;
        // uv_vectors: v runs from corner 0 to 1 (and 3 to 2), u between those edges.
        const Vec2* st = s_.uv;
        const Vec2 e1 = st[0] + (st[1] - st[0]) * v, e2 = st[3] + (st[2] - st[3]) * v;
        h.uv = e1 + (e2 - e1) * u;
        h.has_uv = true;
    }

    scene::BicubicPatch s_;
    Patch cp_;
    Bounds3 box_;
    std::vector<Node> nodes_;
    std::vector<Leaf> leaves_;
};

}  // namespace

std::unique_ptr<Primitive> make_bicubic_patch(const scene::BicubicPatch& s, const Transform& xf,
                                              const char** why) {
    bool finite = std::isfinite(s.flatness);
    for (const auto& row : s.points)
        for (const Vec3& p : row) finite = finite && is_finite(xf.point(p));
    if (!finite || s.u_steps > 12 || s.v_steps > 12) {
        *why = "bicubic_patch with non-finite control points or more than 12 steps";
        return nullptr;
    }
    return std::make_unique<BicubicPatchPrim>(s, xf);
}

}  // namespace glint::render
