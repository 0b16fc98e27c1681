// Real roots of polynomials of any degree up to kMaxSolveDegree inside a bounded interval, for
// the spline and implicit shapes (prism, lathe, sor, blob, poly). The same construction as
// poly_roots.h: roots of the derivative cut the interval into monotone pieces, each holding at
// most one root, found by safeguarded Newton iteration. Leading coefficients too small to matter
// on the interval are dropped first, so near-degenerate equations (a ray parallel to a sweep)
// keep their real roots instead of blowing up.
#pragma once

namespace glint::render {

constexpr int kMaxSolveDegree = 16;

// c: coefficients ascending (c[0] + c[1] x + ...). Writes the roots in [lo, hi] ascending,
// returns how many. Leading terms below 1e-15 of the largest term at max(|lo|, |hi|) are dropped.
int solve_in_interval(const double* c, int degree, double lo, double hi, double* roots);

double eval_polynomial(const double* c, int degree, double x);

}  // namespace glint::render
