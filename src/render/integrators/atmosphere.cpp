#include "render/integrators/atmosphere.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "core/noise.h"

namespace glint::render {
namespace {

// POV-Ray draws the rainbow jitter from the thread's random number stream, which depends on
// the render order; glint hashes the ray direction instead, so images do not depend on the
// thread count (the noise looks alike, the pixels differ).
double direction_random(const Vec3& d) {
    uint64_t h = std::bit_cast<uint64_t>(d.x) * 0x9E3779B97F4A7C15ull;
    h ^= std::bit_cast<uint64_t>(d.y) + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2);
    h ^= std::bit_cast<uint64_t>(d.z) + 0x85157AF5ull + (h << 6) + (h >> 2);
    h ^= h >> 33;
    h *= 0xFF51AFD7ED558CCDull;
    h ^= h >> 33;
    return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);
}

}  // namespace

Atmosphere::Atmosphere(const scene::Scene& scene)
    : fogs_(scene.fogs), rainbows_(scene.rainbows), noise_generator_(scene.global.noise_generator) {
    for (const scene::Rainbow& r : rainbows_) {
        // Parse_Rainbow: the color_map becomes a gradient x pigment indexed at <index, 0, 0>.
        scene::Pigment p;
        p.kind = scene::PatternKind::Gradient;
        p.params.vector = Vec3(1, 0, 0);
        p.color_map = r.color_map;
        rainbow_maps_.push_back(p);
    }
}

Color Atmosphere::apply(const Vec3& origin, const Vec3& dir, double depth,
                        const Color& color) const {
    Color c = color;
    if (!rainbows_.empty()) c = rainbow(dir, depth, c);
    if (!fogs_.empty()) c = fog(origin, dir, depth, c);
    return c;
}

Color Atmosphere::rainbow(const Vec3& dir, double depth, const Color& color) const {
    // ComputeRainbow: the bows seen along `dir` are averaged; filter and transmit only matter
    // for the alpha channel, which glint does not write.
    Color sum;
    int n = 0;
    for (size_t i = 0; i < rainbows_.size(); ++i) {
        const scene::Rainbow& r = rainbows_[i];
        if (r.color_map.empty() || r.distance == 0.0 || r.width == 0.0) continue;
        // Angle between the ray and the bow's up vector, in the plane across the antisolar
        // direction.
        double x = dot(dir, r.right);
        double y = dot(dir, r.up);
        double l = x * x + y * y;
        if (l > 0.0) y /= std::sqrt(l);
        double angle = std::fabs(std::acos(std::clamp(y, -1.0, 1.0)));
        if (angle > r.arc_angle) continue;
        double d = dot(dir, r.antisolar);
        if (d < 0.0) continue;
        double index = (std::acos(std::min(d, 1.0)) - r.angle) / r.width;
        if (r.jitter > 0.0) index += (2.0 * direction_random(dir) - 1.0) * r.jitter;
        if (!(index >= 0.0 && index <= 1.0 - kPovEpsilon)) continue;
        scene::ColorFT cr;
        pigments_.evaluate(rainbow_maps_[i], {Vec3(index, 0, 0), {}, false}, &cr);
        double fade = 0.0;
        if (r.falloff_width > 0.0 && angle > r.falloff_angle) {
            fade = (angle - r.falloff_angle) / r.falloff_width;
            fade = (3.0 - 2.0 * fade) * fade * fade;
        }
        double k = std::exp(-depth / r.distance);
        // The color's transmit is the least attenuation.
        k = std::max(k, fade * (1.0 - cr.transmit) + cr.transmit);
        double ki = 1.0 - k;
        double f = cr.filter * ki;
        sum += Color(k * color.r * ((1.0 - f) + f * cr.rgb.r) + ki * cr.rgb.r,
                     k * color.g * ((1.0 - f) + f * cr.rgb.g) + ki * cr.rgb.g,
                     k * color.b * ((1.0 - f) + f * cr.rgb.b) + ki * cr.rgb.b);
        ++n;
    }
    if (n == 0) return color;
    return sum * (1.0 / n);
}

double Atmosphere::fog_attenuation(const scene::Fog& fog, const Vec3& origin, const Vec3& dir,
                                   double width) const {
    TurbulenceParams turb{fog.octaves, fog.omega, fog.lambda};
    // The further away, the less influence turbulence has.
    auto turbulent_width = [&](const Vec3& at) {
        Vec3 p(at.x * fog.turbulence.x, at.y * fog.turbulence.y, at.z * fog.turbulence.z);
        double k = std::exp(-width / fog.distance);
        return width *
               (1.0 - k * std::min(1.0, turbulence(p, turb, noise_generator_) * fog.turb_depth));
    };
    if (fog.type != scene::FogType::Ground) {
        // ComputeConstantFogColour.
        if (fog.turbulent) width = turbulent_width(origin + dir * (width / 2.0));
        return std::exp(-width / fog.distance);
    }
    // ComputeGroundFogColour: density 1 below the offset, 1 / (1 + h^2) above it; the mean
    // density along the ray comes from the integral atan(h).
    Vec3 p1 = origin;
    Vec3 p2 = p1 + dir * width;
    double start = (dot(p1, fog.up) - fog.offset) / fog.alt;
    double end = (dot(p2, fog.up) - fog.offset) / fog.alt;
    double density;
    if (start <= 0.0) {
        density = end <= 0.0 ? 1.0 : (std::atan(end) - start) / (end - start);
    } else if (end <= 0.0) {
        density = (std::atan(start) - end) / (start - end);
    } else {
        double delta = start - end;
        density = std::fabs(delta) > kPovEpsilon ? (std::atan(start) - std::atan(end)) / delta
                                                  : 1.0 / (start * start + 1.0);
    }
    if (fog.turbulent) width = turbulent_width((p1 + p2) * 0.5);
    return std::exp(-width * density / fog.distance);
}

Color Atmosphere::fog(const Vec3& origin, const Vec3& dir, double depth,
                      const Color& color) const {
    // ComputeFog: each fog attenuates what lies behind it and adds its own color.
    Color sum_att(1.0);
    Color sum_col;
    for (const scene::Fog& f : fogs_) {
        if (!(std::fabs(f.distance) > kPovEpsilon)) continue;
        double att = fog_attenuation(f, origin, dir, depth);
        att = std::max(att, f.color.transmit);  // transmit: the least transmittance
        const Color& c = f.color.rgb;
        const double filter = f.color.filter;
        sum_att *= Color(att * ((1.0 - filter) + filter * c.r), att * ((1.0 - filter) + filter * c.g),
                         att * ((1.0 - filter) + filter * c.b));
        sum_col += c * (1.0 - att);
    }
    return sum_col + sum_att * color;
}

}  // namespace glint::render
