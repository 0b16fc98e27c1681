// A small chi-square goodness-of-fit toolkit for the BSDF sampling tests (VALIDATION.md case
// 13), following the method of pbrt-v3's and Mitsuba's BSDF tests: sampled directions are
// binned on a (theta, phi) grid around an axis, the pdf is integrated over each bin by adaptive
// Simpson quadrature, bins with an expected count below 5 are pooled, and the chi-square
// statistic gives a p-value (regularized upper incomplete gamma function).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <vector>

#include "core/math.h"
#include "core/special.h"
#include "render/bsdf/bsdf.h"

namespace glint::chi2 {

// Survival function of the chi-square distribution with `dof` degrees of freedom.
inline double chi2_pvalue(double chi2, int dof) {
    if (dof <= 0) return 1.0;
    return regularized_gamma_q(0.5 * dof, 0.5 * chi2);
}

// Per-test significance that keeps the family-wise rate at `alpha` over `tests` tests (Sidak).
inline double sidak(double alpha, int tests) { return 1.0 - std::pow(1.0 - alpha, 1.0 / tests); }

struct Result {
    double chi2 = 0;
    int dof = 0;
    double pvalue = 1;
    // Samples in bins whose expected count is 0 (a sampled direction the pdf calls impossible).
    double impossible = 0;
};

// Pools every bin whose expected count is below `min_expected` (smallest first, as pbrt-v3
// does) and returns the statistic. An observed count where nothing is expected fails outright.
inline Result chi2_test(const std::vector<double>& observed, const std::vector<double>& expected,
                        double total, double min_expected = 5) {
    std::vector<size_t> order(observed.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return expected[a] < expected[b]; });
    Result r;
    double pooled_obs = 0, pooled_exp = 0;
    int pooled = 0;
    for (size_t i : order) {
        if (expected[i] <= 0) {
            r.impossible += observed[i];
        } else if (expected[i] < min_expected ||
                   (pooled_exp > 0 && pooled_exp < min_expected)) {
            pooled_obs += observed[i];
            pooled_exp += expected[i];
            ++pooled;
        } else {
            r.chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
            ++r.dof;
        }
    }
    if (pooled > 0) {
        r.chi2 += (pooled_obs - pooled_exp) * (pooled_obs - pooled_exp) / pooled_exp;
        ++r.dof;
    }
    --r.dof;
    r.pvalue = r.impossible > total * 1e-5 ? 0.0 : chi2_pvalue(r.chi2, r.dof);
    return r;
}

// Adaptive Simpson quadrature of f over [a, b] to absolute tolerance eps (Lyness 1969),
// starting from `splits` equal pieces so a narrow peak is not missed by the first five points.
inline double adaptive_simpson(const std::function<double(double)>& f, double a, double b,
                               double eps, int max_depth, int splits = 4) {
    struct Rec {
        const std::function<double(double)>& f;
        double go(double a, double b, double fa, double fm, double fb, double whole, double eps,
                  int depth) const {
            const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
            const double flm = f(lm), frm = f(rm);
            const double left = (m - a) / 6 * (fa + 4 * flm + fm);
            const double right = (b - m) / 6 * (fm + 4 * frm + fb);
            const double both = left + right;
            if (depth <= 0 || std::fabs(both - whole) <= 15 * eps)
                return both + (both - whole) / 15;
            return go(a, m, fa, flm, fm, left, eps / 2, depth - 1) +
                   go(m, b, fm, frm, fb, right, eps / 2, depth - 1);
        }
    } rec{f};
    double sum = 0;
    const double h = (b - a) / splits;
    for (int i = 0; i < splits; ++i) {
        const double x0 = a + i * h, x1 = i + 1 == splits ? b : x0 + h, xm = 0.5 * (x0 + x1);
        const double f0 = f(x0), fm = f(xm), f1 = f(x1);
        sum += rec.go(x0, x1, f0, fm, f1, (x1 - x0) / 6 * (f0 + 4 * fm + f1), eps / splits,
                      max_depth);
    }
    return sum;
}

// A (theta, phi) grid of the whole sphere around `frame.n`. Theta edges are either uniform in
// cos theta (broad lobes) or geometric from width / 8 up to pi (a lobe about `width` wide
// around the axis gets many bins).
class SphereGrid {
public:
    SphereGrid(const render::Frame& frame, int n_theta, int n_phi, double width)
        : frame_(frame), n_phi_(n_phi) {
        edges_.push_back(0);
        if (width >= 0.5) {
            for (int i = 1; i < n_theta; ++i)
                edges_.push_back(std::acos(1.0 - 2.0 * i / n_theta));
        } else {
            const double t1 = width / 8;
            for (int i = 1; i < n_theta; ++i)
                edges_.push_back(t1 * std::pow(kPi / t1, (i - 1.0) / (n_theta - 1.0)));
        }
        edges_.push_back(kPi);
    }
    int n_theta() const { return static_cast<int>(edges_.size()) - 1; }
    int n_phi() const { return n_phi_; }
    int bins() const { return n_theta() * n_phi_; }

    int bin_of(const Vec3& world) const {
        const Vec3 l = frame_.to_local(world);
        const double theta = std::atan2(std::sqrt(l.x * l.x + l.y * l.y), l.z);
        double phi = std::atan2(l.y, l.x);
        if (phi < 0) phi += 2 * kPi;
        int it = static_cast<int>(std::upper_bound(edges_.begin(), edges_.end(), theta) -
                                  edges_.begin()) - 1;
        it = std::clamp(it, 0, n_theta() - 1);
        const int ip = std::clamp(static_cast<int>(phi / (2 * kPi) * n_phi_), 0, n_phi_ - 1);
        return it * n_phi_ + ip;
    }

    // Integral of density(world direction) over each bin (solid angle measure).
    std::vector<double> integrate(const std::function<double(const Vec3&)>& density,
                                  double eps) const {
        std::vector<double> out(bins());
        const double dphi = 2 * kPi / n_phi_;
        for (int it = 0; it < n_theta(); ++it)
            for (int ip = 0; ip < n_phi_; ++ip) {
                const double p0 = ip * dphi, p1 = p0 + dphi;
                auto over_phi = [&](double theta) {
                    const double st = std::sin(theta), ct = std::cos(theta);
                    if (st == 0) return 0.0;
                    auto g = [&](double phi) {
                        const Vec3 l(st * std::cos(phi), st * std::sin(phi), ct);
                        return density(frame_.to_world(l));
                    };
                    return st * adaptive_simpson(g, p0, p1, eps / st, 6, 2);
                };
                out[static_cast<size_t>(it * n_phi_ + ip)] =
                    adaptive_simpson(over_phi, edges_[it], edges_[it + 1], eps, 6, 2);
            }
        return out;
    }

private:
    render::Frame frame_;
    int n_phi_;
    std::vector<double> edges_;
};

// A fixed-seed generator of uniform doubles in [0, 1) (splitmix64), independent of the
// standard library's distributions so the tests draw the same numbers everywhere.
class Rng {
public:
    explicit Rng(uint64_t seed) : state_(seed) {}
    double next() {
        uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        z ^= z >> 31;
        return static_cast<double>(z >> 11) * 0x1p-53;
    }

private:
    uint64_t state_;
};

}  // namespace glint::chi2
