#include "render/film/pixel_filter.h"

#include <algorithm>
#include <cmath>

namespace glint::render {

namespace {
constexpr int kTable = 1024;
constexpr double kTwoPi = 6.283185307179586;
}  // namespace

PixelFilter::PixelFilter(PixelFilterKind kind, double width) : kind_(kind) {
    width = std::max(width, 1e-4);
    switch (kind) {
        case PixelFilterKind::GlintBox: half_ = 0.5; return;
        case PixelFilterKind::Box: half_ = 0.5 * width; return;
        // Cycles widens these (film.cpp): Gaussian's support is 3 widths, Blackman-Harris's 2.
        case PixelFilterKind::Gaussian: half_ = 1.5 * width; break;
        case PixelFilterKind::BlackmanHarris: half_ = width; break;
    }
    cdf_.assign(kTable + 1, 0.0);
    for (int i = 0; i < kTable; ++i) {
        const double x = -half_ + (i + 0.5) * (2 * half_ / kTable);
        double f;
        if (kind == PixelFilterKind::Gaussian) {
            const double v = x * 6.0 / (3 * width);
            f = std::exp(-2.0 * v * v);
        } else {
            const double v = kTwoPi * (x / (2 * width) + 0.5);
            f = 0.35875 - 0.48829 * std::cos(v) + 0.14128 * std::cos(2 * v) -
                0.01168 * std::cos(3 * v);
        }
        cdf_[i + 1] = cdf_[i] + std::max(f, 0.0);
    }
    for (double& c : cdf_) c /= cdf_.back();
}

double PixelFilter::offset(double u) const {
    if (cdf_.empty()) return (u - 0.5) * 2 * half_;
    // The bin holding u, then linearly within it.
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u);
    const int i = std::clamp(static_cast<int>(it - cdf_.begin()) - 1, 0, kTable - 1);
    const double span = cdf_[i + 1] - cdf_[i];
    const double t = span > 0 ? (u - cdf_[i]) / span : 0.5;
    return -half_ + (i + t) * (2 * half_ / kTable);
}

}  // namespace glint::render
