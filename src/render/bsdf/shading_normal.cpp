#include "render/bsdf/shading_normal.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace glint::render {

Vec3 valid_reflection_normal(const Vec3& ng_in, const Vec3& wo, const Vec3& n_in) {
    // Work on the viewer's side of the surface, as Cycles does (it flips both normals of a
    // back-facing hit), and hand the result back on the side n came in.
    const double side = dot(ng_in, wo) < 0 ? -1.0 : 1.0;
    const Vec3 ng = ng_in * side;
    const Vec3 n = n_in * side;

    // A grazing view may reflect as grazingly as it arrives, hence the 0.9 (ng . wo).
    const double iz = dot(wo, ng);
    const double threshold = std::min(0.9 * iz, 0.01);
    const Vec3 r = n * (2 * dot(n, wo)) - wo;
    if (dot(ng, r) >= threshold) return n_in;

    // The new normal lies in the plane of ng (z) and n's tangential part (x): (sqrt(1 - u),
    // sqrt(u)) with u its z squared. Its mirror direction's height over the surface is
    // 2 (x ix + z iz) z - iz; setting that to the threshold t and squaring gives
    //   4 a u^2 - 4 c u + (t + iz)^2 = 0,   a = ix^2 + iz^2,   c = a + iz t,
    // whose discriminant reduces to 16 ix^2 (a - t^2). Squaring admits a root whose mirror
    // direction lies at -t instead of t; the height test below tells them apart.
    const Vec3 tangential = n - ng * dot(n, ng);
    const double tlen = length(tangential);
    if (!(tlen > 0)) return ng * side;
    const Vec3 x = tangential / tlen;
    const double ix = dot(wo, x);
    const double a = ix * ix + iz * iz;
    if (!(a > 0)) return ng * side;
    const double b = std::sqrt(std::max(0.0, ix * ix * (a - threshold * threshold)));
    const double c = a + iz * threshold;
    const double u1 = (c + b) / (2 * a);
    const double u2 = (c - b) / (2 * a);
    // The same tolerances as Cycles, so that both pick the same normal at the boundaries.
    constexpr double kTol = 1e-5;
    auto admissible = [](double u) { return u > kTol && u <= 1 + kTol; };
    auto normal_of = [](double u) {
        return std::pair<double, double>(std::sqrt(std::max(0.0, 1 - u)),
                                         std::sqrt(std::max(0.0, u)));
    };
    auto height = [&](std::pair<double, double> m) {
        return 2 * (m.first * ix + m.second * iz) * m.second - iz;
    };
    std::pair<double, double> chosen;
    const bool ok1 = admissible(u1), ok2 = admissible(u2);
    if (ok1 && ok2) {
        const auto m1 = normal_of(u1), m2 = normal_of(u2);
        const double h1 = height(m1), h2 = height(m2);
        if (h1 >= kTol && h2 >= kTol)
            chosen = h1 < h2 ? m1 : m2;  // both above: the shallower is closer to n
        else
            chosen = h1 > h2 ? m1 : m2;  // one above: that one
    } else if (ok1 || ok2) {
        chosen = normal_of(ok1 ? u1 : u2);
    } else {
        return ng * side;
    }
    return (x * chosen.first + ng * chosen.second) * side;
}

}  // namespace glint::render
