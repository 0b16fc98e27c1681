#include "render/media/path_medium.h"

#include <algorithm>
#include <cmath>

namespace glint::render {
namespace {

constexpr double kInv4Pi = 1.0 / (4.0 * kPi);

double channel_max(const Color& c) { return std::max(c.r, std::max(c.g, c.b)); }
double average(const Color& c) { return (c.r + c.g + c.b) / 3.0; }

// A lobe's value for cos_theta, the cosine between the light's travel before and after.
double lobe_eval(const PhaseLobe& l, double cos_theta) {
    switch (l.kind) {
        case PhaseKind::HenyeyGreenstein: {
            const double g = l.g, d = 1.0 + g * g - 2.0 * g * cos_theta;
            return kInv4Pi * (1.0 - g * g) / (d * std::sqrt(std::max(d, 1e-300)));
        }
        // POV-Ray's ComputeMediaScatteringAttenuation shapes (their k over 4 pi).
        case PhaseKind::Rayleigh: return kInv4Pi * 0.799372013 * (1.0 + cos_theta * cos_theta);
        case PhaseKind::MieHazy:
            return kInv4Pi * 0.576655375 * (1.0 + 9.0 * std::pow(0.5 * (1.0 + cos_theta), 8.0));
        case PhaseKind::MieMurky:
            return kInv4Pi * 0.495714547 * (1.0 + 50.0 * std::pow(0.5 * (1.0 + cos_theta), 32.0));
    }
    return 0.0;
}

// The pdf with which a lobe samples cos_theta (per solid angle).
double lobe_pdf(const PhaseLobe& l, double cos_theta) {
    return l.kind == PhaseKind::HenyeyGreenstein ? lobe_eval(l, cos_theta) : kInv4Pi;
}

void frame(const Vec3& n, Vec3* t, Vec3* b) {
    // Duff et al. 2017, "Building an orthonormal basis, revisited".
    const double s = std::copysign(1.0, n.z);
    const double a = -1.0 / (s + n.z), bb = n.x * n.y * a;
    *t = Vec3(1.0 + s * n.x * n.x * a, s * bb, -s * n.x);
    *b = Vec3(bb, s + n.y * n.y * a, -n.y);
}

}  // namespace

Color MediumPoint::sigma_s() const {
    Color s;
    for (int i = 0; i < lobe_count; ++i) s += lobes[i].sigma_s;
    return s;
}

namespace {

// The lobes' `f` (value or pdf) mixed by their scattering, for the light travelling along -wi
// into the point and leaving along wo.
double mixture(const MediumPoint& m, const Vec3& wo, const Vec3& wi,
               double (*f)(const PhaseLobe&, double)) {
    const double cos_theta = -dot(wo, wi);
    double sum = 0.0, total = 0.0;
    for (int i = 0; i < m.lobe_count; ++i) {
        const double w = average(m.lobes[i].sigma_s);
        sum += w * f(m.lobes[i], cos_theta);
        total += w;
    }
    return total > 0.0 ? sum / total : 0.0;
}

}  // namespace

double phase_eval(const MediumPoint& m, const Vec3& wo, const Vec3& wi) {
    return mixture(m, wo, wi, lobe_eval);
}

double phase_pdf(const MediumPoint& m, const Vec3& wo, const Vec3& wi) {
    return mixture(m, wo, wi, lobe_pdf);
}

bool phase_sample(const MediumPoint& m, const Vec3& wo, double u0, double u1, double u2,
                  Vec3* wi, double* weight, double* pdf) {
    double total = 0.0;
    for (int i = 0; i < m.lobe_count; ++i) total += average(m.lobes[i].sigma_s);
    if (!(total > 0.0)) return false;
    int pick = m.lobe_count - 1;
    double acc = 0.0;
    for (int i = 0; i < m.lobe_count; ++i) {
        acc += average(m.lobes[i].sigma_s) / total;
        if (u0 < acc) {
            pick = i;
            break;
        }
    }
    const PhaseLobe& l = m.lobes[pick];
    double cos_theta;
    if (l.kind == PhaseKind::HenyeyGreenstein && std::fabs(l.g) > 1e-3) {
        const double g = l.g, s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u1);
        cos_theta = std::clamp((1.0 + g * g - s * s) / (2.0 * g), -1.0, 1.0);
    } else {
        cos_theta = 1.0 - 2.0 * u1;
    }
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    const double phi = 2.0 * kPi * u2;
    Vec3 t, b;
    frame(wo, &t, &b);
    // The light's travel before scattering, at theta from its travel after (wo).
    const Vec3 travel = wo * cos_theta + t * (sin_theta * std::cos(phi)) +
                        b * (sin_theta * std::sin(phi));
    *wi = -travel;
    const double p = phase_pdf(m, wo, *wi);
    *pdf = p;
    if (!(p > 0.0)) return false;
    *weight = phase_eval(m, wo, *wi) / p;
    return true;
}

namespace {
struct Equiangular {
    double delta, d, theta_a, theta_b;
};
bool equiangular_setup(const Vec3& origin, const Vec3& dir, double tmax, const Vec3& light,
                       Equiangular* e) {
    e->delta = dot(light - origin, dir);
    e->d = length(light - origin - dir * e->delta);
    if (!(e->d > 1e-12)) return false;
    e->theta_a = std::atan2(-e->delta, e->d);
    e->theta_b = std::isinf(tmax) ? 0.5 * kPi : std::atan2(tmax - e->delta, e->d);
    return e->theta_b > e->theta_a;
}
}  // namespace

bool equiangular_sample(const Vec3& origin, const Vec3& dir, double tmax, const Vec3& light,
                        double u, double* t, double* pdf) {
    Equiangular e;
    if (!equiangular_setup(origin, dir, tmax, light, &e)) return false;
    const double theta = e.theta_a + u * (e.theta_b - e.theta_a);
    const double x = e.d * std::tan(theta);
    *t = std::clamp(e.delta + x, 0.0, tmax);
    *pdf = e.d / ((e.theta_b - e.theta_a) * (e.d * e.d + x * x));
    return std::isfinite(*t) && *pdf > 0;
}

double equiangular_pdf(const Vec3& origin, const Vec3& dir, double tmax, const Vec3& light,
                       double t) {
    Equiangular e;
    if (!equiangular_setup(origin, dir, tmax, light, &e) || t < 0 || t > tmax) return 0;
    const double x = t - e.delta;
    return e.d / ((e.theta_b - e.theta_a) * (e.d * e.d + x * x));
}

double density_bound(const scene::Pigment& p) {
    if (p.kind == scene::PatternKind::Plain) return std::max(0.0, channel_max(p.color.rgb));
    double bound = 0.0;
    if (!p.entries.empty()) {
        for (const scene::Pigment& e : p.entries) bound = std::max(bound, density_bound(e));
        return bound;
    }
    if (!p.pigment_map.empty()) {
        for (const scene::PigmentMapEntry& e : p.pigment_map)
            bound = std::max(bound, density_bound(e.pigment[0]));
        return bound;
    }
    if (!p.color_map.empty()) {
        for (const scene::ColorMapEntry& e : p.color_map)
            bound = std::max(bound, channel_max(e.color.rgb));
        return bound;
    }
    return 1.0;  // POV-Ray's default map: black to white
}

MediumPoint PathMedium::from_closures(const shader::VolumeClosures& v) {
    MediumPoint m;
    Color scattering;
    for (int i = 0; i < v.count; ++i) {
        scattering += v.lobes[i].sigma_s;
        if (m.lobe_count < MediumPoint::kMaxLobes)
            m.lobes[m.lobe_count++] = {PhaseKind::HenyeyGreenstein, v.lobes[i].g,
                                       v.lobes[i].sigma_s};
        else
            m.lobes[MediumPoint::kMaxLobes - 1].sigma_s += v.lobes[i].sigma_s;
    }
    const Color a = v.extinction - scattering;
    m.sigma_a = Color(std::max(0.0, a.r), std::max(0.0, a.g), std::max(0.0, a.b));
    m.emission = v.emission;
    return m;
}

PathMedium::PathMedium(const shader::ShaderProgram* program, const shader::GraphShading* shading)
    : program_(program), shading_(shading) {
    homogeneous_ = false;
    emissive_ = true;  // (unknown before evaluation)
}

void PathMedium::at(const Vec3& p, int object, const Vec3& dir, MediumPoint* out) const {
    if (!program_) {
        at(p, out);
        return;
    }
    shader::VolumeClosures v;
    program_->evaluate_volume(shading_->volume_globals(object, p, dir), &v);
    *out = from_closures(v);
    const double density = shading_->volume_density(object);
    if (density != 1.0) {
        out->sigma_a *= density;
        out->emission *= density;
        for (int i = 0; i < out->lobe_count; ++i) out->lobes[i].sigma_s *= density;
    }
}

PathMedium::PathMedium(const MediumPoint& constant) : constant_(constant) {
    majorant_ = channel_max(constant.sigma_t());
    emissive_ = !constant.emission.is_black();
}

PathMedium::PathMedium(const std::vector<scene::Media>& media, const PigmentEvaluator* pigments)
    : pigments_(pigments) {
    for (const scene::Media& m : media) {
        Component c;
        // POV-Ray's `extinction` scales the scattering's part of the extinction; the path
        // tracer keeps extinction at least the scattering (anything less would make light).
        c.sigma_s = m.scattering;
        c.sigma_a = m.absorption + m.scattering * std::max(0.0, m.extinction - 1.0);
        c.emission = m.emission;
        switch (m.type) {
            case scene::ScatteringType::Isotropic: break;
            case scene::ScatteringType::HenyeyGreenstein: c.lobe.g = m.eccentricity; break;
            case scene::ScatteringType::Rayleigh: c.lobe.kind = PhaseKind::Rayleigh; break;
            case scene::ScatteringType::MieHazy: c.lobe.kind = PhaseKind::MieHazy; break;
            case scene::ScatteringType::MieMurky: c.lobe.kind = PhaseKind::MieMurky; break;
        }
        c.density = m.density;
        double bound = 1.0;
        for (const scene::Pigment& d : m.density) bound *= density_bound(d);
        majorant_ += channel_max(c.sigma_a + c.sigma_s) * bound;
        emissive_ = emissive_ || !m.emission.is_black();
        if (!m.density.empty()) homogeneous_ = false;
        components_.push_back(std::move(c));
    }
    if (components_.size() > static_cast<size_t>(MediumPoint::kMaxLobes))
        components_.resize(MediumPoint::kMaxLobes);
    if (homogeneous_) {
        at(Vec3(0, 0, 0), &constant_);
        components_.clear();
    }
}

void PathMedium::at(const Vec3& p, MediumPoint* out) const {
    if (components_.empty()) {
        *out = constant_;
        return;
    }
    *out = MediumPoint{};
    for (const Component& c : components_) {
        Color density(1.0);
        for (const scene::Pigment& d : c.density) {
            scene::ColorFT pc;
            if (pigments_->evaluate(d, PatternPoint{p, Vec2{0, 0}, false}, &pc))
                density *= Color(std::max(0.0, pc.rgb.r), std::max(0.0, pc.rgb.g),
                                 std::max(0.0, pc.rgb.b));
            else
                density = Color();
        }
        out->sigma_a += c.sigma_a * density;
        out->emission += c.emission * density;
        PhaseLobe l = c.lobe;
        l.sigma_s = c.sigma_s * density;
        out->lobes[out->lobe_count++] = l;
    }
}

}  // namespace glint::render
