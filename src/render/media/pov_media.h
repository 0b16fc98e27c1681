// POV-Ray 3.7's participating media along one ray segment (media.cpp MediaFunction): the
// segment is split into intervals (more where lights shine, by `ratio`), each interval is
// sampled by `method` 1 (random), 2 (stratified) or 3 (adaptive, recursive to aa_level), and
// each sample adds emission and light scattered towards the viewer (through the light's own
// shadow test) and the optical depth of the density there. The result filters the colour
// arriving from the segment's end and adds the media's own light to it.
#pragma once

#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include "core/math.h"
#include "render/gi/photon_map.h"
#include "render/textures/pigment.h"
#include "scene/scene.h"

namespace glint::render {

class PovMedia {
public:
    // The light arriving at a point from one light, after its shadow test (POV-Ray's
    // TestShadow): false when none does. `dir` is unit, from the point towards the light.
    using LightFn = std::function<bool(size_t light, const Vec3& p, Color* colour, Vec3* dir)>;

    // `lights` are the scene's lights, in the integrator's order; `pigments` evaluates the
    // densities. Both `scene` (whose media are the only ones compute() is given) and
    // `pigments` must outlive this.
    PovMedia(const scene::Scene& scene, const std::vector<scene::Light>& lights,
             const PigmentEvaluator* pigments);

    // The media `media` along origin + t dir, t in [0, depth] (dir unit): `colour`, the light
    // arriving from the far end, becomes what arrives at the origin, and `transm` (the
    // alpha's transmittance) is scaled by the grey transmittance. A shadow ray only
    // attenuates. `light` is called only where a medium scatters.
    void compute(const std::vector<const scene::Media*>& media, const Vec3& origin,
                 const Vec3& dir, double depth, bool shadow, const LightFn& light, Color* colour,
                 double* transm) const;

    // Media photons (POV-Ray's media photon map): where a medium that collects photons
    // scatters, the photons near a sample add their light through its phase function.
    void set_photons(const PhotonMap* photons) { photons_ = photons; }
    // The variance thresholds of method 1/2's extra samples (Media::PostProcess): entry i is
    // the largest variance accepted after i + 1 samples. Exposed for tests.
    static std::vector<double> sample_thresholds(const scene::Media& m);
    // POV-Ray's chdtri: the x with an upper chi-square tail of `y` for `df` degrees of freedom.
    static double chi_square_upper_inverse(double df, double y);

private:
    struct SegmentLight {
        size_t light;
        double s0, s1;
    };
    struct Interval {
        bool lit = false;
        int samples = 0;
        double s0 = 0, s1 = 0, ds = 0;
        Color od, te, te2;
    };
    struct Geometry {  // the light's shape as ComputeOneMediaLightInterval sees it
        scene::LightKind kind;
        Vec3 center, direction;
        double falloff;  // spot: cosine of the falloff angle; cylinder: the falloff radius
        bool interacts;  // media_interaction and not shadowless (a fill light)
    };
    struct Context;  // one compute() call's state (pov_media.cpp)

    void light_intervals(const Context& c, std::vector<SegmentLight>* lit) const;
    void sample(Context& c, Interval& iv, double d0, int method, Color* col, Color* od) const;
    void sample_recursive(Context& c, Interval& iv, double d1, double d3, const Color& c1,
                          const Color& c3, const Color& od1, const Color& od3, int depth,
                          Color* result, Color* od_result) const;

    std::vector<Geometry> lights_;
    const PigmentEvaluator* pigments_;
    const PhotonMap* photons_ = nullptr;
    // ComputeMediaScatteringAttenuation's phase factor for light arriving along `to_light`
    // (unit) and leaving along the ray's `dir`, averaged over the media.
    static double phase(const std::vector<const scene::Media*>& media, const Vec3& to_light,
                        const Vec3& dir);
    // Media::PostProcess's thresholds, for each medium that takes extra samples.
    std::unordered_map<const scene::Media*, std::vector<double>> thresholds_;
};

}  // namespace glint::render
