#include "render/lights/area_light.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

namespace glint::render {
namespace {

// A uniform number in [0, 1) for grid sample (u, v) seen from point p, component k. POV-Ray
// jitters with its thread's random number stream, whose position depends on the render order;
// hashing the shading point instead keeps images independent of the thread count (the noise
// has the same amplitude, its pixels differ from POV-Ray's).
double jitter_random(const Vec3& p, int u, int v, int k) {
    uint64_t h = 0x9E3779B97F4A7C15ull * (static_cast<uint64_t>(u) * 131 + v * 2 + k + 1);
    for (double c : {p.x, p.y, p.z}) {
        h ^= std::bit_cast<uint64_t>(c) + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2);
        h ^= h >> 31;
        h *= 0xBF58476D1CE4E5B9ull;
    }
    h ^= h >> 29;
    h *= 0x94D049BB133111EBull;
    h ^= h >> 32;
    return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);
}

double colour_distance(const Color& a, const Color& b) {
    return std::fabs(a.r - b.r) + std::fabs(a.g - b.g) + std::fabs(a.b - b.b);
}

class AreaSampler {
public:
    AreaSampler(const PreparedLight& light, const Vec3& p, const Color& light_color,
                const PointShadowFn& shadow)
        : light_(light), area_(*light.light().area), p_(p), color_(light_color),
          shadow_(shadow), grid_(static_cast<size_t>(area_.size1) * area_.size2),
          known_(grid_.size(), false) {
        axis1_ = area_.axis1;
        axis2_ = area_.axis2;
        if (area_.orient) {
            // Face the shading point: axes perpendicular to the centre ray, both as long as
            // axis1 ([ENB 9/97]).
            Vec3 dir;
            double depth;
            light.white_ray(p, Vec3(0, 0, 0), &dir, &depth);
            double len1 = length(axis1_);
            Vec3 temp = std::fabs(std::fabs(dir.z) - 1.0) < 0.01 ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
            axis1_ = normalize(cross(dir, temp));
            axis2_ = normalize(cross(dir, axis1_));
            axis1_ *= len1;
            axis2_ *= len1;
        }
    }

    Color run() { return subset(0, 0, area_.size1 - 1, area_.size2 - 1, 0); }

private:
    Color grid_sample(int u, int v) {
        size_t i = static_cast<size_t>(u) * area_.size2 + v;
        if (known_[i]) return grid_[i];
        double ju = u, jv = v;
        if (area_.jitter) {
            ju += jitter_random(p_, u, v, 0) - 0.5;
            jv += jitter_random(p_, u, v, 1) - 0.5;
        }
        Vec3 offset;
        if (area_.circular) {
            // Map the square grid onto a disc, shell by shell.
            ju = ju / (area_.size1 - 1) - 0.5 + 0.001;
            jv = jv / (area_.size2 - 1) - 0.5 + 0.001;
            double scale = std::max(std::fabs(ju), std::fabs(jv)) / std::sqrt(ju * ju + jv * jv);
            offset = axis1_ * (ju * scale) + axis2_ * (jv * scale);
        } else {
            if (area_.size1 > 1) offset += axis1_ * (ju / (area_.size1 - 1) - 0.5);
            if (area_.size2 > 1) offset += axis2_ * (jv / (area_.size2 - 1) - 0.5);
        }
        Vec3 dir;
        double depth;
        light_.white_ray(p_, offset, &dir, &depth);
        Color c = shadow_(dir, depth, color_);
        grid_[i] = c;
        known_[i] = true;
        return c;
    }

    Color subset(int u1, int v1, int u2, int v2, int level) {
        Color s[4] = {grid_sample(u1, v1), grid_sample(u2, v1), grid_sample(u1, v2),
                      grid_sample(u2, v2)};
        if (u2 - u1 > 1 || v2 - v1 > 1) {
            if (level < area_.adaptive || colour_distance(s[0], s[1]) > 0.1 ||
                colour_distance(s[1], s[3]) > 0.1 || colour_distance(s[3], s[2]) > 0.1 ||
                colour_distance(s[2], s[0]) > 0.1) {
                int mu_lo = static_cast<int>(std::floor((u1 + u2) / 2.0));
                int mu_hi = static_cast<int>(std::ceil((u1 + u2) / 2.0));
                int mv_lo = static_cast<int>(std::floor((v1 + v2) / 2.0));
                int mv_hi = static_cast<int>(std::ceil((v1 + v2) / 2.0));
                s[0] = subset(u1, v1, mu_lo, mv_lo, level + 1);
                s[1] = subset(mu_hi, v1, u2, mv_lo, level + 1);
                s[2] = subset(u1, mv_hi, mu_lo, v2, level + 1);
                s[3] = subset(mu_hi, mv_hi, u2, v2, level + 1);
            }
        }
        return (s[0] + s[1] + s[2] + s[3]) * 0.25;
    }

    const PreparedLight& light_;
    const scene::AreaLight& area_;
    Vec3 p_;
    Color color_;
    const PointShadowFn& shadow_;
    Vec3 axis1_, axis2_;
    std::vector<Color> grid_;
    std::vector<bool> known_;
};

}  // namespace

Color area_light_shadow(const PreparedLight& light, const Vec3& p, const Color& light_color,
                        const PointShadowFn& shadow) {
    return AreaSampler(light, p, light_color, shadow).run();
}

}  // namespace glint::render
