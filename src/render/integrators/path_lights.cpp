#include "render/integrators/path_lights.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace glint::render {
namespace {

double average(const Color& c) { return (c.r + c.g + c.b) * (1.0 / 3.0); }

// POV-Ray's cubic_spline(low, high, pos) for the spot cone's edge.
double smooth_step(double low, double high, double pos) {
    if (pos <= low) return 0;
    if (pos >= high) return 1;
    const double t = (pos - low) / (high - low);
    return (3 - 2 * t) * t * t;
}

}  // namespace

PathLights::PathLights(const scene::Scene& scene, const std::vector<Color>& emission)
    : scene_(scene) {
    for (int i = 0; i < static_cast<int>(scene.lights.size()); ++i)
        slots_.push_back({SlotKind::Pov, i});
    emitter_object_.assign(scene.objects.size(), 0);
    auto add = [&](int object, const Vec3& a, const Vec3& b, const Vec3& c, int material) {
        if (material < 0 || material >= static_cast<int>(emission.size())) return;
        const Color& le = emission[material];
        if (!(average(le) > 0)) return;
        Tri t;
        t.p0 = a;
        t.e1 = b - a;
        t.e2 = c - a;
        const Vec3 n = cross(t.e1, t.e2);
        t.area = 0.5 * length(n);
        if (!(t.area > 0) || !std::isfinite(t.area)) return;
        t.n = n / (2 * t.area);
        t.le = le;
        tris_.push_back(t);
        emitter_object_[object] = 1;
    };
    for (int oi = 0; oi < static_cast<int>(scene.objects.size()); ++oi) {
        const scene::Object& o = scene.objects[oi];
        const Transform& x = o.transform;
        if (const auto* tri = std::get_if<scene::Triangle>(&o.shape)) {
            add(oi, x.point(tri->p[0]), x.point(tri->p[1]), x.point(tri->p[2]), o.material);
        } else if (const auto* st = std::get_if<scene::SmoothTriangle>(&o.shape)) {
            add(oi, x.point(st->p[0]), x.point(st->p[1]), x.point(st->p[2]), o.material);
        } else if (const auto* mr = std::get_if<scene::MeshRef>(&o.shape)) {
            if (mr->mesh < 0 || mr->mesh >= static_cast<int>(scene.meshes.size())) continue;
            const scene::Mesh& m = scene.meshes[mr->mesh];
            for (const scene::MeshFace& f : m.faces) {
                const int mat = f.material >= 0 ? f.material : o.material;
                if (mat < 0 || mat >= static_cast<int>(emission.size()) ||
                    !(average(emission[mat]) > 0))
                    continue;
                bool ok = true;
                for (int k = 0; k < 3; ++k)
                    ok = ok && f.v[k] >= 0 && f.v[k] < static_cast<int>(m.positions.size());
                if (!ok) continue;
                add(oi, x.point(m.positions[f.v[0]]), x.point(m.positions[f.v[1]]),
                    x.point(m.positions[f.v[2]]), mat);
            }
        }
    }
    if (!tris_.empty()) {
        double sum = 0;
        tri_cdf_.reserve(tris_.size());
        for (const Tri& t : tris_) {
            sum += t.area * average(t.le);
            tri_cdf_.push_back(sum);
        }
        for (double& v : tri_cdf_) v /= sum;
        tri_total_ = sum;
        slots_.push_back({SlotKind::Triangles, -1});
    }
    has_env_ = average(scene.background.rgb) > 0 ||
               (scene.sky_sphere && !scene.sky_sphere->pigments.empty());
    if (has_env_) slots_.push_back({SlotKind::Environment, -1});
}

Color PathLights::pov_factor(const scene::Light& l, const Vec3& from_light, double dist) const {
    double att = 1;
    if (l.fade_power > 0 && l.fade_distance > 0)
        att = 2.0 / (1.0 + std::pow(dist / l.fade_distance, l.fade_power));
    if (l.kind != scene::LightKind::Point) {
        const Vec3 axis = normalize(l.point_at - l.location);
        const double c = dot(from_light, axis);
        if (c <= 0) return Color();
        double spot = l.tightness > 0 ? std::pow(c, l.tightness) : 1.0;
        const double cos_radius = std::cos(l.radius * kPi / 180);
        const double cos_falloff = std::cos(l.falloff * kPi / 180);
        if (l.radius > 0 && c < cos_radius) spot *= smooth_step(cos_falloff, cos_radius, c);
        att *= spot;
    }
    return l.color * (kPi * att);
}

bool PathLights::sample(int slot, const Vec3& p, Sample2 u, PathLightSample* out) const {
    const Slot& s = slots_[slot];
    switch (s.kind) {
        case SlotKind::Pov: {
            const scene::Light& l = scene_.lights[s.light];
            if (l.parallel) {
                const Vec3 d = l.point_at - l.location;
                if (!(length_squared(d) > 0)) return false;
                out->wi = -normalize(d);
                out->dist = kInfinity;
                out->value = l.color * (kPi / select_prob());
                out->pdf = 0;
                return true;
            }
            Vec3 q = l.location;
            if (l.area) {
                double a = u.u - 0.5, b = u.v - 0.5;
                if (l.area->circular) {
                    // The ellipse inscribed in the rectangle (concentric disc mapping).
                    const double x = 2 * a, y = 2 * b;
                    double r = 0, phi = 0;
                    if (std::fabs(x) > std::fabs(y)) {
                        r = x;
                        phi = (kPi / 4) * (y / x);
                    } else if (y != 0) {
                        r = y;
                        phi = kPi / 2 - (kPi / 4) * (x / y);
                    }
                    a = 0.5 * r * std::cos(phi);
                    b = 0.5 * r * std::sin(phi);
                }
                q = q + l.area->axis1 * a + l.area->axis2 * b;
            }
            const Vec3 d = q - p;
            const double dist = length(d);
            if (!(dist > 0)) return false;
            out->wi = d / dist;
            out->dist = dist;
            out->value = pov_factor(l, -out->wi, dist) / select_prob();
            out->pdf = 0;
            return !out->value.is_black();
        }
        case SlotKind::Triangles: {
            const auto it = std::upper_bound(tri_cdf_.begin(), tri_cdf_.end(), u.u);
            const size_t i = std::min<size_t>(it - tri_cdf_.begin(), tris_.size() - 1);
            const double lo = i > 0 ? tri_cdf_[i - 1] : 0.0;
            const double width = tri_cdf_[i] - lo;
            const double ur = width > 0 ? std::clamp((u.u - lo) / width, 0.0, 1.0) : 0.5;
            const Tri& t = tris_[i];
            const double su = std::sqrt(ur);
            const double b1 = 1 - su, b2 = u.v * su;
            const Vec3 q = t.p0 + t.e1 * b1 + t.e2 * b2;
            const Vec3 d = q - p;
            const double dist = length(d);
            if (!(dist > 0)) return false;
            out->wi = d / dist;
            out->dist = dist;
            const double cos_l = std::fabs(dot(t.n, out->wi));
            out->pdf = triangle_pdf(t.le, dist, cos_l);
            if (!(out->pdf > 0) || !std::isfinite(out->pdf)) return false;
            out->value = t.le / out->pdf;
            return true;
        }
        case SlotKind::Environment: {
            const double z = 1 - 2 * u.u;
            const double r = std::sqrt(std::max(0.0, 1 - z * z));
            const double phi = 2 * kPi * u.v;
            out->wi = Vec3(r * std::cos(phi), r * std::sin(phi), z);
            out->dist = kInfinity;
            out->pdf = environment_pdf();
            out->value = Color(1.0 / out->pdf);
            out->environment = true;
            return true;
        }
    }
    return false;
}

double PathLights::triangle_pdf(const Color& le, double dist, double cos_light) const {
    if (!(tri_total_ > 0) || !(cos_light > 0)) return 0;
    const double pdf_area = average(le) / tri_total_;
    return select_prob() * pdf_area * dist * dist / cos_light;
}

}  // namespace glint::render
