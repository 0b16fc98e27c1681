// Piecewise-constant densities, sampled by inverting their CDFs: the 1D building block of the
// environment's 2D table (lights/environment.h) and of any other tabulated light.
#pragma once

#include <vector>

namespace glint::render {

// A piecewise-constant density on [0, 1) over n equal bins, sampled by inverting its CDF.
class Distribution1D {
public:
    explicit Distribution1D(std::vector<double> f);
    // A point in [0, 1); *bin gets its bin, *pdf its density (with respect to [0, 1)).
    double sample(double u, int* bin, double* pdf) const;
    double pdf(int bin) const { return f_[bin] / integral_; }
    // (1 / n) * sum f: the integral of the unnormalized function.
    double integral() const { return integral_; }
    int size() const { return static_cast<int>(f_.size()); }

private:
    std::vector<double> f_;
    std::vector<double> cdf_;  // n + 1 entries, cdf_[0] = 0, cdf_[n] = 1
    double integral_ = 0;
};

}  // namespace glint::render
