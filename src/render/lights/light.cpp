#include "render/lights/light.h"

#include <cmath>

#include "render/ray.h"

namespace glint::render {
namespace {

// lighting/point.cpp cubic_spline: smooth step from low to high.
double cubic_spline(double low, double high, double pos) {
    if (pos < low) return 0.0;
    if (pos >= high) return 1.0;
    pos = (pos - low) / (high - low);
    return (3 - 2 * pos) * pos * pos;
}

}  // namespace

PreparedLight::PreparedLight(const scene::Light& light) : light_(light) {
    Vec3 d = light.point_at - light.location;
    double len = length(d);
    // POV-Ray normalizes only when the length exceeds EPSILON (parse.cpp Parse_Light_Source).
    direction_ = len > kPovEpsilon ? d / len : d;
    if (light.kind == scene::LightKind::Spot) {
        cos_radius_ = std::cos(light.radius * kPi / 180.0);
        cos_falloff_ = std::cos(light.falloff * kPi / 180.0);
    } else {
        // Cylinder lights keep radius and falloff as distances.
        cos_radius_ = light.radius;
        cos_falloff_ = light.falloff;
    }
}

void PreparedLight::white_ray(const Vec3& p, const Vec3& offset, Vec3* out_dir,
                              double* out_depth) const {
    const scene::Light& l = light_;
    const Vec3 center = l.location + offset;
    Vec3 dir;
    double depth;
    if (l.kind == scene::LightKind::Cylinder) {
        // Parallel beams along point_at -> location; depth is the projection on that axis.
        Vec3 axis = center - l.point_at;
        double axis_len = length(axis);
        depth = dot(center - p, axis) / axis_len;
        dir = axis / axis_len;
    } else {
        Vec3 d = center - p;
        depth = length(d);
        dir = d / depth;
    }
    if (l.parallel) {
        if (l.area) {
            // Parallel area lights: each sample shines along (sample - point_at).
            Vec3 v1 = normalize(center - l.point_at);
            depth *= dot(v1, dir);
            dir = v1;
        } else {
            // Parallel lights: rays along -direction everywhere; depth projected onto it.
            double a = dot(direction_, dir);
            depth *= -a;
            dir = -direction_;
        }
    }
    *out_dir = dir;
    *out_depth = depth;
}

// POV-Ray's ComputeDiffuseLight: the global lights unless the object turned them off, then
// the lights of the object's own group.
bool PreparedLight::lights_object(uint32_t object_flags) const {
    if (light_.group < 0) return (object_flags & kNoGlobalLights) == 0;
    const int group = light_group_of(object_flags);
    if (group == light_.group) return true;
    for (int g : light_.also_groups)
        if (g == group) return true;
    return false;
}

bool PreparedLight::sample(const Vec3& p, LightSample* out) const {
    const scene::Light& l = light_;
    Vec3 dir;
    double depth;
    white_ray(p, Vec3(0, 0, 0), &dir, &depth);

    // Attenuate_Light.
    double att = 1.0;
    if (l.kind == scene::LightKind::Spot) {
        double costheta = -dot(dir, direction_);
        if (costheta <= 0.0) return false;
        att = std::pow(costheta, l.tightness);
        if (cos_radius_ > 0.0 && costheta < cos_radius_)
            att *= cubic_spline(cos_falloff_, cos_radius_, costheta);
    } else if (l.kind == scene::LightKind::Cylinder) {
        Vec3 v1 = p - l.location;
        double k = dot(v1, direction_);
        if (k <= 0.0) return false;
        double len = length(v1 - direction_ * k);
        if (len >= cos_falloff_) return false;
        double dist = 1.0 - len / cos_falloff_;
        att = std::pow(dist, l.tightness);
        if (cos_radius_ > 0.0 && len > cos_radius_)
            att *= cubic_spline(0.0, 1.0 - cos_radius_ / cos_falloff_, dist);
    }
    if (att > 0.0 && l.fade_power > 0.0 && std::fabs(l.fade_distance) > kPovEpsilon)
        att *= 2.0 / (1.0 + std::pow(depth / l.fade_distance, l.fade_power));

    out->dir = dir;
    out->distance = depth;
    out->color = l.color * att;
    // ComputeOneDiffuseLight: lights darker than EPSILON are skipped.
    return std::fabs(out->color.r) >= kPovEpsilon || std::fabs(out->color.g) >= kPovEpsilon ||
           std::fabs(out->color.b) >= kPovEpsilon;
}

double PreparedLight::beam(const Vec3& origin, const Vec3& dir) const {
    const scene::Light& l = light_;
    if (l.kind == scene::LightKind::Spot) {
        const double c = dot(dir, direction_);
        if (c <= 0.0) return 0.0;
        double att = std::pow(c, l.tightness);
        if (cos_radius_ > 0.0) att *= cubic_spline(cos_falloff_, cos_radius_, c);
        return att;
    }
    if (l.kind == scene::LightKind::Cylinder) {
        if (dot(dir, direction_) <= 0.0) return 0.0;
        const double len = length(origin - l.location);
        if (len >= cos_falloff_) return 0.0;
        const double d = 1.0 - len / cos_falloff_;
        double att = std::pow(d, l.tightness);
        if (cos_radius_ > 0.0 && len > cos_radius_)
            att *= cubic_spline(0.0, 1.0 - cos_radius_ / cos_falloff_, d);
        return att;
    }
    return 1.0;
}

std::vector<PreparedLight> prepare_lights(const std::vector<scene::Light>& lights) {
    std::vector<PreparedLight> out;
    out.reserve(lights.size());
    for (const scene::Light& l : lights) out.emplace_back(l);
    return out;
}

}  // namespace glint::render
