// Real roots of a polynomial inside an interval, for the torus quartic. Robust by construction:
// the roots of the derivative split the interval into monotone pieces, each with at most one
// root, found by Newton's method safeguarded with bisection to full double precision. Near-double
// roots (rays grazing a silhouette) are not lost the way closed-form quartic formulas lose them.
#pragma once

namespace glint::render {

constexpr int kMaxPolyDegree = 4;

// Coefficients ascending (c[0] + c[1] x + ... + c[degree] x^degree), c[degree] != 0.
// Writes the roots in [lo, hi] in ascending order, returns how many.
int real_roots(const double* c, int degree, double lo, double hi, double* roots);

double eval_poly(const double* c, int degree, double x);

}  // namespace glint::render
