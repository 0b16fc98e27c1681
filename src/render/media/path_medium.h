// Participating media for the path tracer: what a medium holds at a point (absorption,
// scattering with its phase function, emission, all per unit length) and a bound on its
// extinction (the majorant of null-collision tracking). Made from POV-Ray media (an
// interior's media add up; their densities are patterns) or set directly (Blender's volume
// shaders). Read-only while rendering.
#pragma once

#include <vector>

#include "core/math.h"
#include "render/shader/shading.h"
#include "render/textures/pigment.h"
#include "scene/texture.h"

namespace glint::render {

// The phase functions: Henyey-Greenstein (g = 0: isotropic) and POV-Ray's tabulated shapes,
// each scaled as POV-Ray scales it (its factor over 4 pi): POV-Ray's Rayleigh, Mie hazy and
// Mie murky constants integrate to 1.066, 1.153 and 1.247 over the sphere, not 1, and the path
// tracer keeps them so that its media look as POV-Ray's do.
enum class PhaseKind { HenyeyGreenstein, Rayleigh, MieHazy, MieMurky };

struct PhaseLobe {
    PhaseKind kind = PhaseKind::HenyeyGreenstein;
    double g = 0;
    Color sigma_s;  // this lobe's share of the scattering coefficient
};

// The medium at one point.
struct MediumPoint {
    Color sigma_a;
    Color emission;  // radiance added per unit length
    static constexpr int kMaxLobes = 4;
    PhaseLobe lobes[kMaxLobes];
    int lobe_count = 0;
    Color sigma_s() const;
    Color sigma_t() const { return sigma_a + sigma_s(); }
};

// Phase function value for the angle between the light's travel `wi_travel` reversed (unit,
// towards where the light comes from) and the outgoing direction `wo` (unit, towards where
// it goes): both point away from the scattering point. Weighted sum over the lobes by their
// scattering, divided by the total scattering (returns 0 where it is 0).
double phase_eval(const MediumPoint& m, const Vec3& wo, const Vec3& wi);
// Samples wi given wo: picks a lobe by its scattering, then a direction (HG analytically, the
// tabulated shapes uniformly over the sphere). Returns the weight phase / pdf and the pdf of
// the whole mixture.
// The pdf with which phase_sample picks wi.
double phase_pdf(const MediumPoint& m, const Vec3& wo, const Vec3& wi);
bool phase_sample(const MediumPoint& m, const Vec3& wo, double u0, double u1, double u2,
                  Vec3* wi, double* weight, double* pdf);

class PathMedium {
public:
    PathMedium() = default;
    // One hollow object's POV-Ray media, or the atmosphere's. `pigments` (density patterns)
    // must outlive this.
    PathMedium(const std::vector<scene::Media>& media, const PigmentEvaluator* pigments);
    // A medium the same everywhere.
    explicit PathMedium(const MediumPoint& constant);
    // A Blender volume shader that varies in space: evaluated where it is asked, ray marched
    // as Cycles does (no majorant to track against). `shading` must outlive this.
    PathMedium(const shader::ShaderProgram* program, const shader::GraphShading* shading);
    // Cycles' volume closures as the medium they make.
    static MediumPoint from_closures(const shader::VolumeClosures& v);

    bool homogeneous() const { return homogeneous_; }
    bool marched() const { return program_ != nullptr; }
    // A marched medium at `p` in `object` on a ray along `dir`.
    void at(const Vec3& p, int object, const Vec3& dir, MediumPoint* out) const;
    bool emissive() const { return emissive_; }
    // An upper bound on every channel of sigma_t anywhere in the medium.
    double majorant() const { return majorant_; }
    void at(const Vec3& p, MediumPoint* out) const;

private:
    struct Component {  // one POV-Ray media block
        Color sigma_a, sigma_s, emission;
        PhaseLobe lobe;
        std::vector<scene::Pigment> density;
    };
    std::vector<Component> components_;
    MediumPoint constant_;
    const PigmentEvaluator* pigments_ = nullptr;
    const shader::ShaderProgram* program_ = nullptr;
    const shader::GraphShading* shading_ = nullptr;
    bool homogeneous_ = true;
    bool emissive_ = false;
    double majorant_ = 0.0;
};

// Equiangular sampling (Kulla and Fajardo 2012): a distance t in [0, tmax] along the ray
// origin + t dir (dir unit; tmax may be infinite) with density proportional to the inverse
// square distance to the point `light`. Returns false when the light is on the ray's line.
bool equiangular_sample(const Vec3& origin, const Vec3& dir, double tmax, const Vec3& light,
                        double u, double* t, double* pdf);
double equiangular_pdf(const Vec3& origin, const Vec3& dir, double tmax, const Vec3& light,
                       double t);

// An upper bound of a density pattern's value in every channel (its map's largest entry).
double density_bound(const scene::Pigment& p);

}  // namespace glint::render
