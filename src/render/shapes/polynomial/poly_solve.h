// Real roots of polynomials of any degree up to kMaxSolveDegree inside a bounded interval, for
// the torus, the spline and the implicit shapes (prism, lathe, sor, blob, poly). Robust by
// construction: the roots of the derivative cut the interval into monotone pieces, each holding
// at most one root, found by Newton's method safeguarded with bisection to full double
// precision; near-double roots (rays grazing a silhouette) are not lost the way closed-form
// quartic formulas lose them.
#pragma once

namespace glint::render {

constexpr int kMaxSolveDegree = 16;

// c: coefficients ascending (c[0] + c[1] x + ...), c[degree] != 0, degree <= kMaxSolveDegree.
// Writes the roots in [lo, hi] ascending, returns how many.
int real_roots(const double* c, int degree, double lo, double hi, double* roots);

// The same after dropping leading terms below 1e-15 of the largest term at max(|lo|, |hi|), so
// that near-degenerate equations (a ray parallel to a sweep) keep their real roots instead of
// blowing up; non-finite coefficients give none.
int solve_in_interval(const double* c, int degree, double lo, double hi, double* roots);

double eval_polynomial(const double* c, int degree, double x);

}  // namespace glint::render
