#include "render/sampling/distribution.h"

#include <algorithm>
#include <cmath>

#include "render/sampling/sampler.h"

namespace glint::render {

Distribution1D::Distribution1D(std::vector<double> f) : f_(std::move(f)) {
    const size_t n = f_.size();
    cdf_.assign(n + 1, 0.0);
    for (size_t i = 0; i < n; ++i) {
        if (!(f_[i] >= 0) || !std::isfinite(f_[i])) f_[i] = 0;
        cdf_[i + 1] = cdf_[i] + f_[i] / static_cast<double>(n);
    }
    integral_ = cdf_[n];
    if (!(integral_ > 0)) {
        // Nothing to go by: uniform.
        std::fill(f_.begin(), f_.end(), 1.0);
        for (size_t i = 0; i <= n; ++i) cdf_[i] = static_cast<double>(i) / static_cast<double>(n);
        integral_ = 1;
        return;
    }
    for (size_t i = 1; i < n; ++i) cdf_[i] /= integral_;
    cdf_[n] = 1;
}

double Distribution1D::sample(double u, int* bin, double* pdf) const {
    const int n = size();
    // The last i with cdf_[i] <= u; bins of zero width are never chosen.
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u);
    const int i = std::clamp(static_cast<int>(it - cdf_.begin()) - 1, 0, n - 1);
    const double width = cdf_[i + 1] - cdf_[i];
    const double du = width > 0 ? std::clamp((u - cdf_[i]) / width, 0.0, 1.0) : 0.5;
    *bin = i;
    *pdf = f_[i] / integral_;
    return std::min((i + du) / n, kOneMinusEpsilon);
}

}  // namespace glint::render
