#include "render/textures/fractal_patterns.h"

#include <array>
#include <cmath>

namespace glint::render {
namespace {

using scene::PatternParams;

double fractal_exterior(const PatternParams& params, int iters, double a, double b) {
    const double f = params.exterior_factor;
    switch (params.exterior_type) {
        case 0:
            return f;
        case 1:
            return static_cast<double>(iters) / static_cast<double>(params.iterations);
        case 2:
            return a * f;
        case 3:
            return b * f;
        case 4:
            return a * a * f;
        case 5:
            return b * b * f;
        case 6:
            return std::sqrt(a * a + b * b) * f;
        case 7:
            return static_cast<double>(iters % static_cast<unsigned>(f)) / f;
        case 8:
            return static_cast<double>(iters % static_cast<unsigned>(1 + f)) / f;
        default:
            return 0;
    }
}

double fractal_interior(const PatternParams& params, double a, double b, double mindist2) {
    const double f = params.interior_factor;
    switch (params.interior_type) {
        case 0:
            return f;
        case 1:
            return std::sqrt(mindist2) * f;
        case 2:
            return a * f;
        case 3:
            return b * f;
        case 4:
            return a * a * f;
        case 5:
            return b * b * f;
        case 6:
            return a * a + b * b * f;  // sic: POV-Ray scales only b^2
        default:
            return 0;
    }
}

// POV-Ray's signed binomial coefficients for (a + bi)^n: C(n, k), negated where i^k has a
// negative real or imaginary part (k & 2).
struct BinomialTable {
    static constexpr int kMaxExponent = kMaxFractalExponent;
    std::array<std::array<double, kMaxExponent + 1>, kMaxExponent + 1> c{};
    constexpr BinomialTable() {
        for (int n = 0; n <= kMaxExponent; ++n) {
            long long v = 1;
            for (int k = 0; k <= n; ++k) {
                c[n][k] = static_cast<double>((k & 2) ? -v : v);
                v = v * (n - k) / (k + 1);
            }
        }
    }
};
constexpr BinomialTable kBinomials;

}  // namespace

// mandel and julia with exponent 2: z -> z^2 + c.
double fractal2(const PatternParams& params, const Vec3& p, bool julia) {
    double a = p.x, b = p.y;
    const double cr = julia ? params.julia_param.x : p.x;
    const double ci = julia ? params.julia_param.y : p.y;
    double a2 = a * a, b2 = b * b;
    double mindist2 = a2 + b2;
    const int it_max = params.iterations;
    for (int col = 0; col < it_max; ++col) {
        b = 2.0 * a * b + ci;
        a = a2 - b2 + cr;
        a2 = a * a;
        b2 = b * b;
        double dist2 = a2 + b2;
        if (dist2 < mindist2) mindist2 = dist2;
        if (dist2 > 4.0) return fractal_exterior(params, col, a, b);
    }
    return fractal_interior(params, a, b, mindist2);
}

// mandel and julia with exponent 3 or 4 (POV-Ray's mandel3/4, julia3/4 expand the powers).
double fractal34(const PatternParams& params, const Vec3& p, bool julia, int exponent) {
    double a = p.x, b = p.y;
    const double cr = julia ? params.julia_param.x : p.x;
    const double ci = julia ? params.julia_param.y : p.y;
    double a2 = a * a, b2 = b * b;
    double mindist2 = a2 + b2;
    const int it_max = params.iterations;
    for (int col = 0; col < it_max; ++col) {
        if (exponent == 3) {
            b = 3.0 * a2 * b - b2 * b + ci;
            a = a2 * a - 3.0 * a * b2 + cr;
        } else {
            b = 4.0 * (a2 * a * b - a * b2 * b) + ci;
            a = a2 * a2 - 6.0 * a2 * b2 + b2 * b2 + cr;
        }
        a2 = a * a;
        b2 = b * b;
        double dist2 = a2 + b2;
        if (dist2 < mindist2) mindist2 = dist2;
        if (dist2 > 4.0) return fractal_exterior(params, col, a, b);
    }
    return fractal_interior(params, a, b, mindist2);
}


// mandel/julia with exponents 5..33 (POV-Ray's mandelx/juliax): the power expanded with pow().
double fractalx(const PatternParams& params, const Vec3& p, bool julia, int exponent) {
    double a = p.x, b = p.y;
    const double cr = julia ? params.julia_param.x : p.x;
    const double ci = julia ? params.julia_param.y : p.y;
    double mindist2 = a * a + b * b;
    const auto& coeff = kBinomials.c[exponent];
    const int it_max = params.iterations;
    for (int col = 0; col < it_max; ++col) {
        double new_a = std::pow(a, exponent);
        for (int k = 2; k <= exponent; k += 2)
            new_a += coeff[k] * std::pow(a, exponent - k) * std::pow(b, k);
        double new_b = 0;
        for (int l = 1; l <= exponent; l += 2)
            new_b += coeff[l] * std::pow(a, exponent - l) * std::pow(b, l);
        a = new_a + cr;
        b = new_b + ci;
        double dist2 = a * a + b * b;
        if (dist2 < mindist2) mindist2 = dist2;
        if (dist2 > 4.0) return fractal_exterior(params, col, a, b);
    }
    return fractal_interior(params, a, b, mindist2);
}

}  // namespace glint::render
