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

// POV-Ray's magnet patterns (magnet1m/1j/2m/2j): z -> (N(z) / D(z))^2 where, with c1 = c - 1
// and c2 = c - 2, formula 1 has N = z^2 + c1, D = 2z + c2 and formula 2 has
// N = z^3 + 3 c1 z + c1 c2, D = 3 z^2 + 3 c2 z + c1 c2 + 1. The mandel form starts at z = 0
// with c the point, the julia form at z = the point with c the constant. The orbit escapes
// past |z|^2 = 10000 or when it settles within 0.01 of the fixed point 1.
double magnet(const PatternParams& params, const Vec3& p) {
    const bool julia = params.magnet_julia;
    const double cr = julia ? params.julia_param.x : p.x;
    const double ci = julia ? params.julia_param.y : p.y;
    double a = julia ? p.x : 0.0, b = julia ? p.y : 0.0;
    double a2 = a * a, b2 = b * b;
    double mindist2 = julia ? a2 + b2 : 10000.0;
    // formula 2's constant term c1 c2 (complex)
    const double c1r = cr - 1.0, c2r = cr - 2.0;
    const double k_re = c1r * c2r - ci * ci, k_im = (c1r + c2r) * ci;
    const int it_max = params.iterations;
    for (int col = 0; col < it_max; ++col) {
        double nr, ni, dr, di;
        if (params.magnet_type == 2) {
            nr = a2 * a - 3 * a * b2 + 3 * (a * c1r - b * ci) + k_re;
            ni = 3 * a2 * b - b2 * b + 3 * (a * ci + b * c1r) + k_im;
            dr = 3 * (a2 - b2) + 3 * (a * c2r - b * ci) + k_re + 1;
            di = 6 * a * b + 3 * (a * ci + b * c2r) + k_im;
        } else {
            nr = a2 - b2 + cr - 1;
            ni = 2 * a * b + ci;
            dr = 2 * a + cr - 2;
            di = 2 * b + ci;
        }
        // q = n / d, then z = q^2
        const double den = dr * dr + di * di;
        const double qr = (nr * dr + ni * di) / den;
        const double qi = (ni * dr - nr * di) / den;
        const double qi2 = qi * qi;
        b = 2 * qr * qi;
        a = qr * qr - qi2;
        a2 = a * a;
        b2 = b * b;
        const double dist2 = a2 + b2;
        if (dist2 < mindist2) mindist2 = dist2;
        const double from_one = a - 1;
        if (dist2 > 10000.0 || from_one * from_one + b2 < 1 / 10000.0)
            return fractal_exterior(params, col, a, b);
    }
    return fractal_interior(params, a, b, mindist2);
}

}  // namespace glint::render
