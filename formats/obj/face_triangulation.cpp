#include "formats/obj/face_triangulation.h"

#include <algorithm>
#include <cmath>

namespace glint::obj {
namespace {

struct P2 {
    double x, y;
};

double cross2(const P2& o, const P2& a, const P2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

void fan(int n, std::vector<std::array<int, 3>>* out) {
    for (int i = 1; i + 1 < n; ++i) out->push_back({0, i, i + 1});
}

// Ear clipping of a simple polygon, counter-clockwise in `p`. Ear status is kept per corner
// and recomputed only for the two neighbours of a clipped corner, so the whole cut is O(n^2).
void ear_clip(const std::vector<P2>& p, std::vector<std::array<int, 3>>* out) {
    const int n = static_cast<int>(p.size());
    // Areas within rounding of zero count as zero: a corner exactly on an ear's edge must
    // block it (cutting there leaves a triangle of no area), and projecting the polygon into
    // its plane rounds. 1e-12 of the squared extent is far above that rounding and far below
    // any face a model would have.
    double lo_x = p[0].x, hi_x = p[0].x, lo_y = p[0].y, hi_y = p[0].y;
    for (const P2& q : p) {
        lo_x = std::min(lo_x, q.x), hi_x = std::max(hi_x, q.x);
        lo_y = std::min(lo_y, q.y), hi_y = std::max(hi_y, q.y);
    }
    const double tol = 1e-12 * ((hi_x - lo_x) * (hi_x - lo_x) + (hi_y - lo_y) * (hi_y - lo_y));
    std::vector<int> prev(n), next(n);
    for (int i = 0; i < n; ++i) {
        prev[i] = (i + n - 1) % n;
        next[i] = (i + 1) % n;
    }
    auto convex = [&](int i) { return cross2(p[prev[i]], p[i], p[next[i]]) > tol; };
    auto same = [&](int i, int j) { return p[i].x == p[j].x && p[i].y == p[j].y; };
    auto is_ear = [&](int b) {
        const int a = prev[b], c = next[b];
        if (!convex(b)) return false;
        // A corner inside (or on) the triangle abc makes it no ear; only reflex or flat
        // corners can be inside a convex corner's triangle.
        for (int j = next[c]; j != a; j = next[j]) {
            if (convex(j) || same(j, a) || same(j, b) || same(j, c)) continue;
            if (cross2(p[a], p[b], p[j]) >= -tol && cross2(p[b], p[c], p[j]) >= -tol &&
                cross2(p[c], p[a], p[j]) >= -tol)
                return false;
        }
        return true;
    };
    std::vector<char> ear(n);
    for (int i = 0; i < n; ++i) ear[i] = is_ear(i);
    int remaining = n;
    int cursor = 1;  // the ear after corner 0 first: a convex polygon becomes the fan around 0
    while (remaining > 3) {
        int b = cursor;
        for (int k = 0; k < remaining && !ear[b]; ++k) b = next[b];
        // No ear (a self-intersecting or numerically flat polygon): cut at the cursor anyway,
        // so the loop always ends and every corner is used.
        if (!ear[b]) b = cursor;
        const int a = prev[b], c = next[b];
        out->push_back({a, b, c});
        next[a] = c;
        prev[c] = a;
        --remaining;
        ear[a] = is_ear(a);
        ear[c] = is_ear(c);
        cursor = c;
    }
    // The last three, from the lowest index so that a fan ends on (0, n-2, n-1).
    int first = cursor;
    for (int k = 0, i = cursor; k < 3; ++k, i = next[i]) first = std::min(first, i);
    out->push_back({first, next[first], next[next[first]]});
}

}  // namespace

void triangulate_face(std::span<const Vec3> c, std::vector<std::array<int, 3>>* out) {
    const int n = static_cast<int>(c.size());
    if (n < 3) return;
    if (n == 3) {
        out->push_back({0, 1, 2});
        return;
    }
    if (n == 4) {
        // Corners 1 and 3 on the same side of the diagonal 0-2: it runs outside the quad.
        const Vec3 d01 = c[1] - c[0], d02 = c[2] - c[0], d03 = c[3] - c[0];
        if (dot(cross(d01, d02), cross(d03, d02)) > 0) {
            out->push_back({0, 1, 3});
            out->push_back({1, 2, 3});
        } else {
            out->push_back({0, 1, 2});
            out->push_back({0, 2, 3});
        }
        return;
    }
    // Newell's normal: the polygon's vector area, well defined for non-planar polygons too.
    Vec3 normal;
    for (int i = 0; i < n; ++i) {
        const Vec3& a = c[i];
        const Vec3& b = c[(i + 1) % n];
        normal +=
            Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    const double len = length(normal);
    if (!(len > 0) || !std::isfinite(len) || n > kMaxEarClipCorners) {
        fan(n, out);
        return;
    }
    const Vec3 w = normal / len;
    const Vec3 u =
        normalize(std::fabs(w.x) > 0.9 ? cross(w, Vec3(0, 1, 0)) : cross(w, Vec3(1, 0, 0)));
    const Vec3 v = cross(w, u);  // (u, v, w) right-handed: the polygon runs counter-clockwise
    std::vector<P2> p(n);
    for (int i = 0; i < n; ++i) p[i] = {dot(c[i], u), dot(c[i], v)};
    ear_clip(p, out);
}

}  // namespace glint::obj
