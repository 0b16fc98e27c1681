#include "render/bsdf/bssrdf.h"

#include <cmath>

namespace glint::render {
namespace {

constexpr double kMinRadius = 1e-8;

double& channel(Color& c, int i) { return i == 0 ? c.r : i == 1 ? c.g : c.b; }

// Diffuse reflectance of a half-space of single-scattering albedo a (the dipole model with
// the boundary's A term as 4/3 A).
double dipole_reflectance(double a, double four_thirds_a) {
    const double s = std::sqrt(3 * (1 - a));
    return 0.5 * a * (1 + std::exp(-four_thirds_a * s)) * std::exp(-s);
}

// Its inverse by bisection over [0, 1], 12 halvings as in Cycles (the last midpoint).
double albedo_for_reflectance(double rd, double four_thirds_a) {
    if (rd < 1e-4) return 0;
    if (rd >= 0.995) return 0.999999;
    double lo = 0, hi = 1, mid = 0.5;
    for (int i = 0; i < 12; ++i) {
        mid = 0.5 * (lo + hi);
        if (dipole_reflectance(mid, four_thirds_a) < rd) lo = mid;
        else hi = mid;
    }
    return mid;
}

}  // namespace

int Bssrdf::setup(bool fixed_radius, double ior, Color* diffuse) {
    *diffuse = Color();
    channels = 0;
    for (int i = 0; i < 3; ++i) {
        if (channel(radius, i) < kMinRadius) {
            channel(*diffuse, i) = channel(weight, i);
            channel(weight, i) = 0;
            channel(radius, i) = 0;
        } else {
            ++channels;
        }
    }
    if (channels == 0) return 0;
    if (fixed_radius) {
        radius = radius * (0.25 / kPi);
        return channels;
    }
    // Jensen's fit of the diffuse Fresnel reflectance F_dr for the index ratio.
    const double inv = 1 / ior;
    const double fdr = inv * (-1.440 * inv + 0.710) + 0.668 + 0.0636 * ior;
    const double four_thirds_a = 4.0 / 3.0 * (1 + fdr) / (1 - fdr);
    for (int i = 0; i < 3; ++i) {
        const double a = albedo_for_reflectance(channel(albedo, i), four_thirds_a);
        channel(radius, i) *= std::sqrt(3 * (1 - a));
    }
    return channels;
}

double Bssrdf::sample_weight() const {
    return std::fabs((weight.r + weight.g + weight.b) / 3) * channels;
}

}  // namespace glint::render
