// Special functions the renderer and its tests share.
#pragma once

#include <algorithm>
#include <cmath>

namespace glint {

// The regularized upper incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a): the
// lower one's series for x < a + 1 (Q = 1 - P), else Q's continued fraction by the modified
// Lentz method (Abramowitz & Stegun 6.5.29 and 6.5.31). The chi-square distribution's upper
// tail for k degrees of freedom is Q(k / 2, x / 2).
inline double regularized_gamma_q(double a, double x) {
    if (x <= 0) return 1.0;
    const double log_front = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 100000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::fabs(term) < std::fabs(sum) * 1e-15) break;
        }
        return std::max(0.0, 1.0 - sum * std::exp(log_front));
    }
    constexpr double kTiny = 1e-300;
    double b = x + 1 - a, c = 1 / kTiny, d = 1 / b, h = d;
    for (int n = 1; n < 100000; ++n) {
        const double an = -n * (n - a);
        b += 2;
        d = an * d + b;
        if (std::fabs(d) < kTiny) d = kTiny;
        c = b + an / c;
        if (std::fabs(c) < kTiny) c = kTiny;
        d = 1 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1) < 1e-15) break;
    }
    return std::exp(log_front) * h;
}

}  // namespace glint
