#include "render/shapes/polynomial/poly_solve.h"

#include <algorithm>
#include <cmath>

namespace glint::render {

double eval_polynomial(const double* c, int degree, double x) {
    double v = c[degree];
    for (int i = degree - 1; i >= 0; --i) v = v * x + c[i];
    return v;
}

namespace {

double eval_derivative(const double* c, int degree, double x) {
    double v = degree * c[degree];
    for (int i = degree - 1; i >= 1; --i) v = v * x + i * c[i];
    return v;
}

// The single root of a monotone piece [a, b] whose ends have opposite signs.
double refine(const double* c, int degree, double a, double b, double fa) {
    double x = 0.5 * (a + b);
    for (int it = 0; it < 200; ++it) {
        double f = eval_polynomial(c, degree, x);
        if (f == 0) return x;
        if ((f < 0) == (fa < 0)) a = x;
        else b = x;
        double df = eval_derivative(c, degree, x);
        double nx = df != 0 ? x - f / df : a;
        if (!(nx > a && nx < b)) nx = 0.5 * (a + b);
        double mid = 0.5 * (a + b);
        if (nx == x || !(b > a) || mid == a || mid == b) return nx;
        x = nx;
    }
    return x;
}

}  // namespace

int real_roots(const double* c, int degree, double lo, double hi, double* out) {
    if (degree <= 0 || !(lo <= hi)) return 0;
    if (degree == 1) {
        if (c[1] == 0) return 0;
        double r = -c[0] / c[1];
        if (r >= lo && r <= hi) {
            out[0] = r;
            return 1;
        }
        return 0;
    }
    double d[kMaxSolveDegree];
    for (int i = 1; i <= degree; ++i) d[i - 1] = i * c[i];
    double crit[kMaxSolveDegree];
    int nc = real_roots(d, degree - 1, lo, hi, crit);
    double pts[kMaxSolveDegree + 2];
    int np = 0;
    pts[np++] = lo;
    for (int i = 0; i < nc; ++i)
        if (crit[i] > pts[np - 1]) pts[np++] = crit[i];
    if (hi > pts[np - 1]) pts[np++] = hi;
    int n = 0;
    double fa = eval_polynomial(c, degree, pts[0]);
    if (fa == 0) out[n++] = pts[0];
    for (int i = 1; i < np; ++i) {
        double fb = eval_polynomial(c, degree, pts[i]);
        if (fb == 0) {
            out[n++] = pts[i];
        } else if (fa != 0 && (fa < 0) != (fb < 0)) {
            out[n++] = refine(c, degree, pts[i - 1], pts[i], fa);
        }
        fa = fb;
    }
    return n;
}

int solve_in_interval(const double* c, int degree, double lo, double hi, double* roots) {
    if (!(lo <= hi) || degree > kMaxSolveDegree) return 0;
    // Drop leading terms that cannot change the value on [lo, hi] beyond rounding.
    double s = std::max({std::fabs(lo), std::fabs(hi), 1e-300});
    double biggest = 0;
    double sk = 1;
    double mag[kMaxSolveDegree + 1];
    for (int i = 0; i <= degree; ++i) {
        if (!std::isfinite(c[i])) return 0;
        mag[i] = std::fabs(c[i]) * sk;
        biggest = std::max(biggest, mag[i]);
        sk *= s;
    }
    if (!(biggest > 0)) return 0;
    while (degree > 0 && mag[degree] <= 1e-15 * biggest) --degree;
    if (degree == 0) return 0;
    return real_roots(c, degree, lo, hi, roots);
}

}  // namespace glint::render
