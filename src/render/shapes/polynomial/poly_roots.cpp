#include "render/shapes/polynomial/poly_roots.h"

#include <cmath>

namespace glint::render {

double eval_poly(const double* c, int degree, double x) {
    double v = c[degree];
    for (int i = degree - 1; i >= 0; --i) v = v * x + c[i];
    return v;
}

namespace {

double eval_deriv(const double* c, int degree, double x) {
    double v = degree * c[degree];
    for (int i = degree - 1; i >= 1; --i) v = v * x + i * c[i];
    return v;
}

// The one root of a monotone piece with f(a), f(b) of opposite signs.
double refine(const double* c, int degree, double a, double b, double fa) {
    double x = 0.5 * (a + b);
    for (int it = 0; it < 200; ++it) {
        double f = eval_poly(c, degree, x);
        if (f == 0) return x;
        if ((f < 0) == (fa < 0)) a = x;
        else b = x;
        double df = eval_deriv(c, degree, x);
        double nx = df != 0 ? x - f / df : a;
        // Newton when it stays strictly inside the bracket, else bisection.
        if (!(nx > a && nx < b)) nx = 0.5 * (a + b);
        if (nx == x || b - a <= 0 || 0.5 * (a + b) == a || 0.5 * (a + b) == b) return nx;
        x = nx;
    }
    return x;
}

}  // namespace

int real_roots(const double* c, int degree, double lo, double hi, double* roots) {
    if (degree <= 0 || !(lo <= hi)) return 0;
    if (degree == 1) {
        double r = -c[0] / c[1];
        if (r >= lo && r <= hi) {
            roots[0] = r;
            return 1;
        }
        return 0;
    }
    double d[kMaxPolyDegree];
    for (int i = 1; i <= degree; ++i) d[i - 1] = i * c[i];
    double pts[kMaxPolyDegree + 1];
    int np = 0;
    pts[np++] = lo;
    double crit[kMaxPolyDegree];
    int nc = real_roots(d, degree - 1, lo, hi, crit);
    for (int i = 0; i < nc; ++i)
        if (crit[i] > pts[np - 1]) pts[np++] = crit[i];
    if (hi > pts[np - 1]) pts[np++] = hi;
    int n = 0;
    double fa = eval_poly(c, degree, pts[0]);
    if (fa == 0) roots[n++] = pts[0];
    for (int i = 1; i < np; ++i) {
        double fb = eval_poly(c, degree, pts[i]);
        if (fb == 0) {
            roots[n++] = pts[i];
        } else if (fa != 0 && (fa < 0) != (fb < 0)) {
            roots[n++] = refine(c, degree, pts[i - 1], pts[i], fa);
        }
        fa = fb;
    }
    return n;
}

}  // namespace glint::render
