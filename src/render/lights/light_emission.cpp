#include "render/lights/light_emission.h"

#include <algorithm>
#include <cmath>

#include "core/float.h"
#include "render/sampling/warp.h"

namespace glint::render {
namespace {

double average(const Color& c) { return (c.r + c.g + c.b) * (1.0 / 3.0); }

// Index of the CDF interval holding u, and u rescaled within it.
size_t pick(const std::vector<double>& cdf, double u, double* rescaled) {
    const auto it = std::upper_bound(cdf.begin(), cdf.end(), u);
    const size_t i = std::min<size_t>(it - cdf.begin(), cdf.size() - 1);
    const double lo = i > 0 ? cdf[i - 1] : 0.0;
    const double width = cdf[i] - lo;
    *rescaled = width > 0 ? std::clamp((u - lo) / width, 0.0, 0x1.fffffffffffffp-1) : 0.5;
    return i;
}

// The cosine below which a POV-Ray light sends nothing (-1: it shines everywhere), as
// PathLights::pov_factor shapes its cone.
double cone_cos(const scene::Light& l) {
    if (l.kind == scene::LightKind::Point) return -1;
    // (pov_factor cuts at the falloff, or at the radius where a falloff inside it leaves the
    // edge there: the wider of the two bounds both.)
    if (l.radius > 0) return std::max(0.0, std::cos(std::max(l.falloff, l.radius) * kPi / 180));
    return 0;
}

// A CDF from weights; false when they sum to nothing.
bool make_cdf(const std::vector<double>& w, std::vector<double>* cdf, double* total) {
    cdf->clear();
    double sum = 0;
    for (double x : w) cdf->push_back(sum += std::max(0.0, x));
    *total = sum;
    if (!(sum > 0) || !std::isfinite(sum)) return false;
    for (double& c : *cdf) c /= sum;
    cdf->back() = 1;
    return true;
}

}  // namespace

LightEmission::LightEmission(const scene::Scene& scene, const PathLights& lights,
                             const EnvironmentDistribution::Radiance& environment,
                             const Vec3& center, double radius)
    : scene_(scene), lights_(lights), environment_(environment), center_(center),
      radius_(radius) {
    // The emitting shapes by power: pi x area x average radiance, both faces of triangles
    // and discs, the outside of spheres.
    std::vector<double> w;
    for (const PathLights::Tri& t : lights_.tris_) w.push_back(2 * kPi * t.area * average(t.le));
    for (const PathLights::Shape& e : lights_.shapes_)
        w.push_back((e.sphere ? 1 : 2) * kPi * e.area * average(e.le));
    if (!w.empty()) make_cdf(w, &emitter_cdf_, &emitter_total_);
    std::vector<double> power;
    for (int s = 0; s < static_cast<int>(lights_.slots_.size()); ++s) {
        if (lights_.slots_[s].kind == PathLights::SlotKind::Blender && unsupported_.empty())
            unsupported_ = "Blender lights";
        power.push_back(slot_power(s));
    }
    if (!make_cdf(power, &slot_cdf_, &total_)) total_ = 0;
    slot_prob_.assign(power.size(), 0.0);
    for (size_t s = 0; s < power.size(); ++s)
        if (total_ > 0) slot_prob_[s] = std::max(0.0, power[s]) / total_;
}

double LightEmission::slot_power(int slot) const {
    const PathLights::Slot& s = lights_.slots_[slot];
    const double disc = kPi * radius_ * radius_;
    switch (s.kind) {
        case PathLights::SlotKind::Pov: {
            const scene::Light& l = scene_.lights[s.light];
            const double intensity = kPi * average(l.color);
            if (l.parallel) return intensity * disc;
            return intensity * 2 * kPi * (1 - cone_cos(l));
        }
        case PathLights::SlotKind::Blender:
            return 0;
        case PathLights::SlotKind::Emitters:
            return emitter_total_;
        case PathLights::SlotKind::Environment: {
            // The mean radiance over a spiral of directions, times 4 pi, through the disc.
            constexpr int kN = 256;
            double sum = 0;
            for (int i = 0; i < kN; ++i) {
                const double z = 1 - (2 * i + 1.0) / kN;
                const double r = std::sqrt(std::max(0.0, 1 - z * z));
                const double phi = i * 2.399963229728653;  // the golden angle
                sum += average(environment_(Vec3(r * std::cos(phi), r * std::sin(phi), z)));
            }
            return 4 * kPi * sum / kN * disc;
        }
    }
    return 0;
}

double LightEmission::first_flight(int light, double dist) const {
    if (light < 0) return 1;
    const scene::Light& l = scene_.lights[light];
    double fade = 1;
    if (l.fade_power > 0 && l.fade_distance > 0)
        fade = 2.0 / (1.0 + std::pow(dist / l.fade_distance, l.fade_power));
    return dist * dist * fade;
}

bool LightEmission::sample(double u_light, Sample2 u_pos, Sample2 u_dir,
                           EmissionSample* out) const {
    if (!(total_ > 0)) return false;
    double u;
    const int slot = static_cast<int>(pick(slot_cdf_, u_light, &u));
    if (!(slot_prob_[slot] > 0)) return false;
    if (!sample_slot(slot, u_pos, u_dir, out)) return false;
    out->power *= 1 / slot_prob_[slot];
    return std::isfinite(out->power.r) && std::isfinite(out->power.g) &&
           std::isfinite(out->power.b) && !out->power.is_black();
}

bool LightEmission::sample_slot(int slot, Sample2 u_pos, Sample2 u_dir,
                                EmissionSample* out) const {
    const PathLights::Slot& s = lights_.slots_[slot];
    out->pov_light = -1;
    // A parallel beam along `dir` through the disc around the scene: its start, and its flux
    // for the irradiance it brings across the beam.
    auto beam = [&](const Vec3& dir, const Color& irradiance) {
        Vec3 a, b;
        tangents(dir, &a, &b);
        const double r = radius_ * std::sqrt(u_pos.u), phi = 2 * kPi * u_pos.v;
        out->origin = center_ - dir * radius_ + a * (r * std::cos(phi)) + b * (r * std::sin(phi));
        out->dir = dir;
        out->power = irradiance * (kPi * radius_ * radius_);
        return true;
    };
    switch (s.kind) {
        case PathLights::SlotKind::Pov: {
            const scene::Light& l = scene_.lights[s.light];
            if (l.parallel) {
                const Vec3 d = l.point_at - l.location;
                if (!(length_squared(d) > 0)) return false;
                return beam(normalize(d), l.color * kPi);
            }
            Vec3 q = l.location;
            if (l.area) {
                // Uniform over the rectangle, or over the ellipse inscribed in it.
                double a = u_pos.u - 0.5, b = u_pos.v - 0.5;
                if (l.area->circular) {
                    const double r = 0.5 * std::sqrt(u_pos.u), phi = 2 * kPi * u_pos.v;
                    a = r * std::cos(phi);
                    b = r * std::sin(phi);
                }
                q = q + l.area->axis1 * a + l.area->axis2 * b;
            }
            const double cmin = cone_cos(l);
            Vec3 dir;
            double pdf;
            if (cmin <= -1) {
                dir = uniform_sphere(u_dir);
                pdf = 1 / (4 * kPi);
            } else {
                const Vec3 axis = l.point_at - l.location;
                if (!(length_squared(axis) > 0)) return false;
                dir = uniform_cone_around(normalize(axis), cmin, u_dir);
                pdf = 1 / (2 * kPi * (1 - cmin));
            }
            out->origin = q;
            out->dir = dir;
            // The intensity pi x colour x cone (at the fade distance POV-Ray's fade is 1);
            // first_flight() applies the distance once the photon lands.
            out->power = lights_.pov_factor(l, dir, l.fade_distance) * (1 / pdf);
            out->pov_light = s.light;
            return true;
        }
        case PathLights::SlotKind::Blender:
            return false;
        case PathLights::SlotKind::Emitters: {
            if (emitter_cdf_.empty()) return false;
            double ur;
            const size_t i = pick(emitter_cdf_, u_pos.u, &ur);
            const double prob = (i > 0 ? emitter_cdf_[i] - emitter_cdf_[i - 1] : emitter_cdf_[0]);
            if (!(prob > 0)) return false;
            Vec3 q, n;
            double area, size = 0;  // size: the emitter's extent, for the rounding bound
            Color le;
            bool two_sided = true;
            if (i < lights_.tris_.size()) {
                const PathLights::Tri& t = lights_.tris_[i];
                const double su = std::sqrt(ur);
                q = t.p0 + t.e1 * (1 - su) + t.e2 * (u_pos.v * su);
                n = t.n;
                size = length(t.e1) + length(t.e2);
                area = t.area;
                le = t.le;
            } else {
                const PathLights::Shape& e = lights_.shapes_[i - lights_.tris_.size()];
                le = e.le;
                if (e.sphere && e.cone) {
                    n = uniform_sphere({ur, u_pos.v});
                    q = e.center + n * e.radius;
                    size = e.radius;
                    area = e.area;
                    two_sided = false;
                } else if (e.sphere) {
                    // Uniform on the object-space sphere: the world's area element there is
                    // |M a x M b| for tangents a, b of the object-space normal.
                    const Vec3 no = uniform_sphere({ur, u_pos.v});
                    q = e.to_world.point(e.center + no * e.radius);
                    Vec3 a, b;
                    tangents(no, &a, &b);
                    n = cross(e.to_world.vector(a), e.to_world.vector(b));
                    const double scale = length(n);
                    if (!(scale > 0)) return false;
                    n = n / scale;
                    if (dot(n, q - e.to_world.point(e.center)) < 0) n = -n;
                    area = 4 * kPi * e.radius * e.radius * scale;
                    size = e.radius * std::sqrt(scale) + length(e.to_world.point(e.center));
                    two_sided = false;
                } else {
                    const double rho = std::sqrt(e.inner2 + ur * (1 - e.inner2));
                    const double phi = 2 * kPi * u_pos.v;
                    q = e.center + e.a1 * (rho * std::cos(phi)) + e.a2 * (rho * std::sin(phi));
                    n = e.n;
                    size = length(e.a1) + length(e.a2);
                    area = e.area;
                }
            }
            Sample2 ud = u_dir;
            if (two_sided) {
                // Either face, half the photons each.
                if (ud.u < 0.5) {
                    ud.u *= 2;
                } else {
                    ud.u = std::min(2 * ud.u - 1, 0x1.fffffffffffffp-1);
                    n = -n;
                }
            }
            out->dir = cosine_around(n, ud);
            // Off the emitter by the rounding bound of the computed point, so the photon
            // does not find its own surface at t ~ 0.
            const double err = 32 * 0x1p-53;
            const Vec3 bound(std::fabs(q.x) * err, std::fabs(q.y) * err, std::fabs(q.z) * err);
            out->origin = offset_ray_origin(q, bound + Vec3(1, 1, 1) * (size * err), n, out->dir);
            // Radiance x cos / (area density x cos / pi x face choice).
            out->power = le * (kPi * area * (two_sided ? 2 : 1) / prob);
            return true;
        }
        case PathLights::SlotKind::Environment: {
            // Towards the sky along w with its density; the photon comes the other way.
            Vec3 w;
            double pdf = 1 / (4 * kPi);
            if (lights_.env_) {
                if (!lights_.env_->sample(u_dir, &w, &pdf)) return false;
            } else {
                w = uniform_sphere(u_dir);
            }
            if (!(pdf > 0)) return false;
            return beam(-w, environment_(w) * (1 / pdf));
        }
    }
    return false;
}

}  // namespace glint::render
