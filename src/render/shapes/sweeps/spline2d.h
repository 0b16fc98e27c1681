// Plane curve segments of POV-Ray's prism and lathe (prism.cpp Compute_Prism, lathe.cpp
// Compute_Lathe): each segment is a cubic p(w) = ((a w + b) w + c) w + d for w in [0, 1], from
// 2 (linear), 3 (quadratic), or 4 (cubic Catmull-Rom, Bezier) control points, with the bounding
// rectangle of the curve piece.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/math.h"
#include "render/shapes/polynomial/poly_solve.h"
#include "scene/shape.h"

namespace glint::render {

struct SplineSegment {
    Vec2 a, b, c, d;
    Vec2 lo, hi;  // bounding rectangle

    Vec2 at(double w) const {
        return {((a.x * w + b.x) * w + c.x) * w + d.x, ((a.y * w + b.y) * w + c.y) * w + d.y};
    }
    Vec2 tangent(double w) const {
        return {(3 * a.x * w + 2 * b.x) * w + c.x, (3 * a.y * w + 2 * b.y) * w + c.y};
    }
};

// The segment starting at control point p[0] (p must hold 2, 3 or 4 points for the type).
inline SplineSegment make_segment(scene::SplineType type, const Vec2* p) {
    SplineSegment s;
    auto comp = [&](auto get, double& a, double& b, double& c, double& d) {
        switch (type) {
            case scene::SplineType::Linear:
                a = 0, b = 0, c = get(p[1]) - get(p[0]), d = get(p[0]);
                break;
            case scene::SplineType::Quadratic:
                a = 0;
                b = 0.5 * get(p[0]) - get(p[1]) + 0.5 * get(p[2]);
                c = -0.5 * get(p[0]) + 0.5 * get(p[2]);
                d = get(p[1]);
                break;
            case scene::SplineType::Cubic:
                a = -0.5 * get(p[0]) + 1.5 * get(p[1]) - 1.5 * get(p[2]) + 0.5 * get(p[3]);
                b = get(p[0]) - 2.5 * get(p[1]) + 2.0 * get(p[2]) - 0.5 * get(p[3]);
                c = -0.5 * get(p[0]) + 0.5 * get(p[2]);
                d = get(p[1]);
                break;
            case scene::SplineType::Bezier:
                a = get(p[3]) - 3.0 * get(p[2]) + 3.0 * get(p[1]) - get(p[0]);
                b = 3.0 * get(p[2]) - 6.0 * get(p[1]) + 3.0 * get(p[0]);
                c = 3.0 * get(p[1]) - 3.0 * get(p[0]);
                d = get(p[0]);
                break;
        }
    };
    comp([](const Vec2& v) { return v.x; }, s.a.x, s.b.x, s.c.x, s.d.x);
    comp([](const Vec2& v) { return v.y; }, s.a.y, s.b.y, s.c.y, s.d.y);
    // Bounds: the end points and the extrema inside (Bezier: its control polygon, as POV-Ray).
    Vec2 e0 = s.at(0), e1 = s.at(1);
    s.lo = {std::min(e0.x, e1.x), std::min(e0.y, e1.y)};
    s.hi = {std::max(e0.x, e1.x), std::max(e0.y, e1.y)};
    if (type == scene::SplineType::Bezier) {
        for (int i = 0; i < 4; ++i) {
            s.lo = {std::min(s.lo.x, p[i].x), std::min(s.lo.y, p[i].y)};
            s.hi = {std::max(s.hi.x, p[i].x), std::max(s.hi.y, p[i].y)};
        }
    } else {
        for (int axis = 0; axis < 2; ++axis) {
            double c3[3] = {axis ? s.c.y : s.c.x, 2 * (axis ? s.b.y : s.b.x),
                            3 * (axis ? s.a.y : s.a.x)};
            double r[3];
            int n = solve_in_interval(c3, 2, 0, 1, r);
            for (int k = 0; k < n; ++k) {
                Vec2 q = s.at(r[k]);
                double v = axis ? q.y : q.x;
                if (axis) {
                    s.lo.y = std::min(s.lo.y, v);
                    s.hi.y = std::max(s.hi.y, v);
                } else {
                    s.lo.x = std::min(s.lo.x, v);
                    s.hi.x = std::max(s.hi.x, v);
                }
            }
        }
    }
    return s;
}

// How many control points a segment of `type` spans.
inline int segment_points(scene::SplineType type) {
    switch (type) {
        case scene::SplineType::Linear: return 2;
        case scene::SplineType::Quadratic: return 3;
        default: return 4;
    }
}

// Crossings of the ray from (u, v) towards +u with the segments, POV-Ray's in_curve rule:
// odd means inside.
template <class Segments>
bool curve_contains(const Segments& segs, double u, double v) {
    int crossings = 0;
    for (const SplineSegment& s : segs) {
        if (v < s.lo.y || v > s.hi.y || u > s.hi.x) continue;
        double c[4] = {s.d.y - v, s.c.y, s.b.y, s.a.y};
        double r[3];
        int n = solve_in_interval(c, 3, 0, 1, r);
        for (int k = 0; k < n; ++k)
            if (s.at(r[k]).x >= u) ++crossings;
    }
    return crossings & 1;
}

}  // namespace glint::render
