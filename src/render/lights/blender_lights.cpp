#include "render/lights/blender_lights.h"

#include <algorithm>
#include <cmath>

namespace glint::render {
namespace {

using scene::BlenderLightType;

constexpr double kDeg = kPi / 180;

// Two unit vectors completing the unit vector n to an orthonormal frame.
void frame(const Vec3& n, Vec3* a, Vec3* b) {
    *a = normalize(std::fabs(n.x) > 0.9 ? cross(n, Vec3(0, 1, 0)) : cross(n, Vec3(1, 0, 0)));
    *b = cross(n, *a);
}

// [0,1)^2 onto the unit disc, preserving area (Shirley and Chiu's concentric map).
void concentric_disc(Sample2 u, double* a, double* b) {
    const double x = 2 * u.u - 1, y = 2 * u.v - 1;
    if (x == 0 && y == 0) {
        *a = *b = 0;
        return;
    }
    double r, phi;
    if (std::fabs(x) > std::fabs(y)) {
        r = x;
        phi = (kPi / 4) * (y / x);
    } else {
        r = y;
        phi = kPi / 2 - (kPi / 4) * (x / y);
    }
    *a = r * std::cos(phi);
    *b = r * std::sin(phi);
}

double smoothstep01(double x) { return x * x * (3 - 2 * x); }

// Whitted's area_light grid for a Blender light's soft shadows: kGrid x kGrid samples, all
// traced (adaptive level 2 subdivides a 5 x 5 grid fully), jittered.
constexpr int kGrid = 5;
constexpr int kGridLevels = 2;
// Where the Whitted integrator puts the sun: far along -direction (a POV-Ray parallel light
// needs a location; its shadow rays end at the plane through it).
constexpr double kSunDistance = 1e9;

}  // namespace

CyclesLight::CyclesLight(const scene::Light& light) {
    const scene::BlenderLight& b = *light.blender;
    type_ = b.type;
    co_ = light.location;
    dir_ = normalize(b.direction);
    strength_ = light.color * b.power;
    camera_ = b.visible_camera;
    switch (type_) {
        case BlenderLightType::Point:
        case BlenderLightType::Spot:
            radius_ = std::max(0.0, b.radius);
            invarea_ = radius_ > 0 ? 1 / (kPi * radius_ * radius_) : 1.0;
            visible_ = radius_ > 0;
            if (type_ == BlenderLightType::Spot) {
                spot_cos_ = std::cos(b.spot_size * kDeg / 2);
                spot_smooth_ = (1 - spot_cos_) * b.spot_blend;
            }
            break;
        case BlenderLightType::Sun: {
            const double half = b.angle * kDeg / 2;
            tan_half_ = std::tan(half);
            cos_half_ = std::cos(half);
            const double area = kPi * tan_half_ * tan_half_;
            invarea_ = area > 0 ? 1 / area : 1.0;
            visible_ = area > 0;
            break;
        }
        case BlenderLightType::Area: {
            axis_u_ = normalize(b.axis_x) * b.size_x;
            axis_v_ = normalize(b.axis_y) * b.size_y;
            round_ = b.ellipse;
            double area = b.size_x * b.size_y;
            if (round_) area *= kPi / 4;
            invarea_ = area > 0 ? 1 / area : 1.0;
            visible_ = area > 0;
            // Spread 0..180 degrees becomes the slat angle 90..0 (at least 1 degree of
            // spread); the normalisation integrates cos x (1 - tan x tan a) sin x over
            // [0, pi/2 - a], as scene/light.cpp states.
            const double spread = std::max(b.spread * kDeg, 1.0 * kDeg);
            const double slat = 0.5 * (kPi - spread);
            tan_spread_ = std::tan(slat);
            normalize_spread_ = 2 / (2 + (2 * slat - kPi) * tan_spread_);
            if (!(tan_spread_ > 1e-12)) tan_spread_ = 0;
            break;
        }
    }
}

double CyclesLight::spot_attenuation(const Vec3& from_light) const {
    // Cycles 3.4: the cosine to the axis itself, zero outside the cone, times a smoothstep
    // over the blend band just inside its edge.
    double a = dot(dir_, from_light);
    if (a <= spot_cos_) return 0;
    const double t = a - spot_cos_;
    if (spot_smooth_ != 0 && t < spot_smooth_) a *= smoothstep01(t / spot_smooth_);
    return a;
}

double CyclesLight::spread_attenuation(const Vec3& from_light) const {
    if (!(tan_spread_ > 0)) return 1;
    const double c = dot(dir_, from_light);
    if (!(c > 0)) return 0;
    const double s = std::sqrt(std::max(0.0, 1 - c * c));
    return std::max(0.0, (1 - tan_spread_ * (s / c)) * normalize_spread_);
}

bool CyclesLight::sample_rect(const Vec3& p, Vec3* centre, Vec3* au, Vec3* av) const {
    *centre = co_;
    *au = axis_u_;
    *av = axis_v_;
    if (!(tan_spread_ > 0)) return true;
    // Only the disc of radius h / tan_spread around p's foot on the plane can light p.
    const double h = dot(dir_, p - co_);
    const Vec3 foot = p - dir_ * h;
    const double radius = std::fabs(h) / tan_spread_;
    const double lu = length(axis_u_), lv = length(axis_v_);
    const Vec3 u = axis_u_ / lu, v = axis_v_ / lv;
    const double cu = dot(u, foot - co_), cv = dot(v, foot - co_);
    const double u0 = std::max(cu - radius, -0.5 * lu), u1 = std::min(cu + radius, 0.5 * lu);
    const double v0 = std::max(cv - radius, -0.5 * lv), v1 = std::min(cv + radius, 0.5 * lv);
    if (!(u0 < u1) || !(v0 < v1)) return false;
    *centre = co_ + u * (0.5 * (u0 + u1)) + v * (0.5 * (v0 + v1));
    *au = u * (u1 - u0);
    *av = v * (v1 - v0);
    return true;
}

double spherical_rectangle(const Vec3& p, const Vec3& corner, const Vec3& ex, const Vec3& ey,
                           Sample2 u, Vec3* q) {
    // The rectangle in a frame at p: x, y along its edges, z0 < 0 the plane's offset.
    const double ex_len = length(ex), ey_len = length(ey);
    if (!(ex_len > 0) || !(ey_len > 0)) return 0;
    const Vec3 x = ex / ex_len, y = ey / ey_len;
    Vec3 z = cross(x, y);
    const Vec3 d = corner - p;
    double z0 = dot(d, z);
    if (z0 > 0) {
        z = -z;
        z0 = -z0;
    }
    if (!(z0 < 0)) return 0;
    const double x0 = dot(d, x), y0 = dot(d, y);
    const double x1 = x0 + ex_len, y1 = y0 + ey_len;
    // Unit normals of the four planes through p and an edge, and the angles between them.
    const auto unit = [](Vec3 v) { return normalize(v); };
    const Vec3 n0 = unit(Vec3(0, z0, -y0)), n1 = unit(Vec3(-z0, 0, x1));
    const Vec3 n2 = unit(Vec3(0, -z0, y1)), n3 = unit(Vec3(z0, 0, -x0));
    const auto angle = [](const Vec3& a, const Vec3& b) {
        return std::acos(std::clamp(-dot(a, b), -1.0, 1.0));
    };
    const double g0 = angle(n0, n1), g1 = angle(n1, n2), g2 = angle(n2, n3),
                 g3 = angle(n3, n0);
    const double k = 2 * kPi - g2 - g3;
    const double solid = g0 + g1 - k;
    if (!(solid > 0) || !std::isfinite(solid)) return 0;
    if (!q) return solid;
    // Invert the solid angle along x, then the y-extent at that x.
    const double b0 = n0.z, b1 = n2.z;
    const double au = u.u * solid + k;
    const double fu = (std::cos(au) * b0 - b1) / std::sin(au);
    double cu = 1 / std::sqrt(fu * fu + b0 * b0);
    if (!(fu > 0)) cu = -cu;
    cu = std::clamp(cu, -1.0, 1.0);
    double xu = -(cu * z0) / std::max(std::sqrt(1 - cu * cu), 1e-12);
    xu = std::clamp(xu, x0, x1);
    const double dd = std::sqrt(xu * xu + z0 * z0);
    const double h0 = y0 / std::sqrt(dd * dd + y0 * y0);
    const double h1 = y1 / std::sqrt(dd * dd + y1 * y1);
    const double hv = h0 + u.v * (h1 - h0);
    const double hv2 = hv * hv;
    const double yv = hv2 < 1 - 1e-12 ? hv * dd / std::sqrt(1 - hv2) : y1;
    *q = p + x * xu + y * std::clamp(yv, y0, y1) + z * z0;
    return solid;
}

bool CyclesLight::sample(const Vec3& p, Sample2 u, Sample* out) const {
    switch (type_) {
        case BlenderLightType::Point:
        case BlenderLightType::Spot: {
            const Vec3 to_p = p - co_;
            if (!(length_squared(to_p) > 0)) return false;
            const Vec3 n = normalize(to_p);  // the disc faces p
            Vec3 q = co_;
            if (radius_ > 0) {
                Vec3 a, b;
                frame(n, &a, &b);
                double da, db;
                concentric_disc(u, &da, &db);
                q = q + (a * da + b * db) * radius_;
            }
            const Vec3 d = q - p;
            const double t = length(d);
            if (!(t > 0)) return false;
            out->wi = d / t;
            out->dist = t;
            const double cos_l = -dot(n, out->wi);
            if (!(cos_l > 0)) return false;
            double eval = invarea_ / (4 * kPi);
            if (type_ == BlenderLightType::Spot) eval *= spot_attenuation(-out->wi);
            if (!(eval > 0)) return false;
            const double pdf = invarea_ * t * t / cos_l;
            out->value = strength_ * (eval / pdf);
            out->pdf = radius_ > 0 ? pdf : 0.0;
            return std::isfinite(pdf);
        }
        case BlenderLightType::Sun: {
            Vec3 d = dir_;
            if (tan_half_ > 0) {
                Vec3 a, b;
                frame(dir_, &a, &b);
                double da, db;
                concentric_disc(u, &da, &db);
                d = normalize(dir_ + (a * da + b * db) * tan_half_);
            }
            const double c = dot(dir_, d);
            out->wi = -d;
            out->dist = kInfinity;
            out->value = strength_;  // eval_fac equals the pdf
            out->pdf = tan_half_ > 0 ? invarea_ / (c * c * c) : 0.0;
            return true;
        }
        case BlenderLightType::Area: {
            if (dot(co_ - p, dir_) > 0) return false;  // behind the light
            Vec3 q;
            double pdf;
            if (round_) {
                double da, db;
                concentric_disc(u, &da, &db);
                q = co_ + axis_u_ * (0.5 * da) + axis_v_ * (0.5 * db);
                const Vec3 d = q - p;
                const double t = length(d);
                if (!(t > 0)) return false;
                const double cos_l = -dot(dir_, d / t);
                if (!(cos_l > 0)) return false;
                pdf = invarea_ * t * t / cos_l;
            } else {
                Vec3 centre, au, av;
                if (!sample_rect(p, &centre, &au, &av)) return false;
                const double solid =
                    spherical_rectangle(p, centre - au * 0.5 - av * 0.5, au, av, u, &q);
                if (!(solid > 0)) return false;
                pdf = 1 / solid;
            }
            const Vec3 d = q - p;
            const double t = length(d);
            if (!(t > 0)) return false;
            out->wi = d / t;
            out->dist = t;
            const double eval = 0.25 * invarea_ * spread_attenuation(-out->wi);
            if (!(eval > 0)) return false;
            out->value = strength_ * (eval / pdf);
            out->pdf = pdf;
            return std::isfinite(pdf) && pdf > 0;
        }
    }
    return false;
}

bool CyclesLight::intersect(const Vec3& from, const Vec3& dir, double tmin, double tmax,
                            double* t, Color* radiance, double* pdf) const {
    if (!visible_) return false;
    switch (type_) {
        case BlenderLightType::Point:
        case BlenderLightType::Spot: {
            const Vec3 to_from = from - co_;
            if (!(length_squared(to_from) > 0)) return false;
            const Vec3 n = normalize(to_from);  // the disc faces the ray's origin
            const double cos_l = -dot(dir, n);
            if (!(cos_l > 0)) return false;
            const double th = dot(to_from, n) / cos_l;
            if (!(th > tmin && th <= tmax)) return false;
            const Vec3 hp = from + dir * th - co_;
            if (length_squared(hp) > radius_ * radius_) return false;
            double eval = invarea_ / (4 * kPi);
            if (type_ == BlenderLightType::Spot) eval *= spot_attenuation(-dir);
            if (!(eval > 0)) return false;
            *t = th;
            *radiance = strength_ * eval;
            *pdf = invarea_ * th * th / cos_l;
            return true;
        }
        case BlenderLightType::Sun: {
            if (!std::isinf(tmax)) return false;
            const double c = -dot(dir_, dir);
            if (c < cos_half_) return false;
            *t = kInfinity;
            *pdf = invarea_ / (c * c * c);
            *radiance = strength_ * *pdf;
            return true;
        }
        case BlenderLightType::Area: {
            const double cos_l = -dot(dir, dir_);
            if (!(cos_l > 0)) return false;  // one-sided
            const double th = dot(from - co_, dir_) / cos_l;
            if (!(th > tmin && th <= tmax)) return false;
            const Vec3 hp = from + dir * th - co_;
            const double su = dot(hp, axis_u_) / length_squared(axis_u_);
            const double sv = dot(hp, axis_v_) / length_squared(axis_v_);
            if (round_) {
                if (4 * (su * su + sv * sv) > 1) return false;
            } else if (std::fabs(su) > 0.5 || std::fabs(sv) > 0.5) {
                return false;
            }
            const double eval = 0.25 * invarea_ * spread_attenuation(-dir);
            if (!(eval > 0)) return false;
            if (round_) {
                *pdf = invarea_ * th * th / cos_l;
            } else {
                Vec3 centre, au, av;
                if (!sample_rect(from, &centre, &au, &av)) return false;
                const double solid = spherical_rectangle(from, centre - au * 0.5 - av * 0.5, au,
                                                         av, Sample2{}, nullptr);
                if (!(solid > 0)) return false;
                *pdf = 1 / solid;
            }
            *t = th;
            *radiance = strength_ * eval;
            return true;
        }
    }
    return false;
}

bool CyclesLight::whitted_color(const Vec3& p, Color* color) const {
    if (type_ == BlenderLightType::Sun) {
        *color = strength_ * (1 / kPi);
        return true;
    }
    const Vec3 d = p - co_;
    const double dist2 = length_squared(d);
    if (!(dist2 > 0)) return false;
    const Vec3 from_light = d / std::sqrt(dist2);
    double intensity;  // radiant intensity towards p over the strength
    if (type_ == BlenderLightType::Area) {
        // Radiance strength / (4 A) over the area A, seen at the angle from the normal.
        const double c = dot(dir_, from_light);
        if (!(c > 0)) return false;
        intensity = 0.25 * c * spread_attenuation(from_light);
    } else {
        intensity = 1 / (4 * kPi);
        if (type_ == BlenderLightType::Spot) intensity *= spot_attenuation(from_light);
    }
    if (!(intensity > 0)) return false;
    *color = strength_ * (intensity / (kPi * dist2));
    return true;
}

scene::Light whitted_light(const scene::Light& light) {
    if (!light.blender) return light;
    const scene::BlenderLight& b = *light.blender;
    scene::Light l = light;
    l.kind = scene::LightKind::Point;
    l.parallel = false;
    l.shadowless = false;
    l.fade_distance = l.fade_power = 0;
    l.area.reset();
    scene::AreaLight grid;
    grid.size1 = grid.size2 = kGrid;
    grid.adaptive = kGridLevels;
    grid.jitter = true;
    const Vec3 dir = normalize(b.direction);
    switch (b.type) {
        case BlenderLightType::Point:
        case BlenderLightType::Spot:
            if (b.radius > 0) {
                // A disc facing the shading point: POV-Ray's circular, oriented area light.
                grid.axis1 = Vec3(2 * b.radius, 0, 0);
                grid.axis2 = Vec3(0, 2 * b.radius, 0);
                grid.circular = grid.orient = true;
                l.area = grid;
            }
            break;
        case BlenderLightType::Sun: {
            l.parallel = true;
            l.location = -dir * kSunDistance;
            l.point_at = Vec3(0, 0, 0);
            if (b.angle > 0) {
                // Parallel area lights shine from each sample towards point_at: the grid spans
                // the sun's cone at that distance.
                Vec3 a, c;
                frame(dir, &a, &c);
                const double extent = 2 * std::tan(b.angle * kDeg / 2) * kSunDistance;
                grid.axis1 = a * extent;
                grid.axis2 = c * extent;
                grid.circular = true;
                l.area = grid;
            }
            break;
        }
        case BlenderLightType::Area:
            grid.axis1 = normalize(b.axis_x) * b.size_x;
            grid.axis2 = normalize(b.axis_y) * b.size_y;
            grid.circular = b.ellipse;
            l.area = grid;
            break;
    }
    return l;
}

std::vector<scene::Light> whitted_lights(const std::vector<scene::Light>& lights) {
    std::vector<scene::Light> out;
    out.reserve(lights.size());
    for (const scene::Light& l : lights) out.push_back(whitted_light(l));
    return out;
}

bool whitted_blender_color(const scene::Light& light, const Vec3& p, Color* color) {
    return CyclesLight(light).whitted_color(p, color);
}

}  // namespace glint::render
