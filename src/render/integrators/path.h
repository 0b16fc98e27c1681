// The Monte Carlo path tracer (--integrator path): unidirectional path tracing with
// next-event estimation and multiple importance sampling (power heuristic, Veach 1997) for
// emissive triangles, spheres and discs and the environment (an HDR sky importance-sampled,
// path_lights.h), Russian roulette after a few bounces, a maximum
// depth, and stochastic alpha; participating media (POV-Ray media, Blender volumes) along
// the way (path_media.cpp, docs/path-tracer.md#participating-media). Materials come from the
// IR's Pbr half, or from the POV-Ray finish through docs/pbr-mapping.md. Prepared once per
// render, read-only while rendering,
// allocation-free per sample; random numbers come from the deterministic PixelSampler.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/bsdf/bsdf.h"
#include "render/bsdf/closure_set.h"
#include "render/bsdf/pov_to_pbr.h"
#include "render/film/aov.h"
#include "render/lights/path_lights.h"
#include "render/media/path_medium.h"
#include "render/prepare/prepared_scene.h"
#include "render/sampling/sampler.h"
#include "render/textures/pigment.h"

namespace glint::render {

struct PathSettings {
    int max_depth = 8;       // bounces after the camera ray (1 = direct light only)
    int rr_start = 3;        // Russian roulette from this bounce on
    // Cycles' Light Paths > Clamping and Filter Glossy (Blender scenes; 0: off, the CLI's
    // unbiased default): a contribution whose |r| + |g| + |b| passes the limit of its bounce
    // (direct: the camera's hit; indirect: after it) is scaled down to it; glossy closures
    // are blurred after a bounce whose pdf was low (Cycles' blur_glossy).
    double clamp_direct = 0;
    double clamp_indirect = 0;
    double filter_glossy = 0;
    bool light_tree = true;  // RenderOptions::light_tree
    // Cycles' bounce limits by kind (-1: none): after a bounce that reaches its kind's limit,
    // the next hit adds its emission and the path ends there. A Blender scene's transparent
    // limit caps the pass-throughs (alpha, transparent closures) instead of kMaxAlphaSkips.
    int diffuse_bounces = -1, glossy_bounces = -1, transmission_bounces = -1,
        transparent_bounces = -1, volume_bounces = -1;
    // Blender's Film > Transparent (RenderOptions::film_transparent).
    bool film_transparent = false;
    double film_transparent_glass = -1;  // RenderOptions::film_transparent_glass
    double volume_step_rate = 1.0;        // RenderOptions::volume_step_rate
    int volume_max_steps = 1024;
    // Equiangular sampling of point lights in homogeneous media, MIS with distance sampling
    // (off: distance sampling alone, for tests).
    bool volume_equiangular = true;
};

// Where a camera path of the photon integrator (gi/sppm.h) stops: its first vertex with a
// BSDF that is not a delta, and what photons arriving there add to the pixel.
struct VisiblePoint {
    bool found = false;
    Vec3 p;        // the hit
    Vec3 ng;       // its geometric normal
    Color beta;    // the path's throughput, over the chance of stopping here
    ClosureSet set{Vec3(0, 0, 1), Vec3(0, 0, 1)};  // the BSDFs there, seen from the path
    int depth = 0;           // bounces (all deltas) before it
    double distance = 0;     // path length from the camera
};

// What a photon meets at a surface (PathIntegrator::photon_surface).
struct PhotonSurface {
    ClosureSet set{Vec3(0, 0, 1), Vec3(0, 0, 1)};
    bool pass = false;  // straight through (alpha, transparent closures)
    Color pass_weight;  // its tint over the chance of passing
};

class PathIntegrator {
public:
    // `prepared` (made for IntegratorKind::Path) must outlive the integrator.
    PathIntegrator(const PreparedScene& prepared, const PathSettings& settings);

    // Radiance along a camera ray. Pair 0 of the sampler is the driver's pixel jitter. With
    // `first`, also what the ray sees at its first visible hit (the AOVs) and how much of its
    // view is transparent (film_transparent's world, holdouts: FirstHit::transparent).
    // With `vp` (the photon integrator's camera pass) the path follows delta bounces only:
    // at its first vertex with other BSDFs it adds their direct light (light sampling alone,
    // no MIS: photons bring the rest), then goes on along a delta lobe or stops there, in
    // proportion to the lobes' sampling chances, and fills *vp where it stops.
    Color li(const Ray& ray, const PixelSampler& sampler, FirstHit* first = nullptr,
             VisiblePoint* vp = nullptr) const;

    // The photon integrator's questions: the lights, the environment's radiance, and the
    // BSDFs a photon arriving along `dir` meets at `hit` (alpha and transparency decided with
    // the uniform `coin`); false where it meets none.
    const PathLights& lights() const { return *lights_; }
    Color environment_radiance(const Vec3& dir) const { return environment(dir); }
    bool photon_surface(Hit& hit, const Vec3& dir, double coin, PhotonSurface* out) const;
    // Why the photon integrator cannot render this scene ("" when it can): media and
    // subsurface scattering it does not carry photons through.
    std::string photon_limits() const;

    // Paths whose radiance was NaN or infinite (dropped, counted).
    uint64_t nonfinite() const { return nonfinite_.load(std::memory_order_relaxed); }
    // Rays traced so far (camera, continuation and shadow rays), for -v's Mrays/s.
    uint64_t rays() const;

private:
    // The media of materials, objects and the world (path_media.cpp), from the constructor.
    void setup_media();
    // The surface at a hit. Bump and normal maps (OBJ/MTL map_Bump) bend hit.n in place.
    // `dir`: the direction of the ray that met `hit` (POV-Ray's aoi pattern reads it).
    SurfacePbr surface(Hit& hit, const Vec3& dir) const;
    // A POV-Ray subsurface finish's BSSRDF (SurfacePbr::subsurface_radius) into `set`.
    void add_pov_subsurface(const SurfacePbr& s, const Hit& hit, const Vec3& dir,
                            bool diffuse_ancestor, ClosureSet* set) const;
    // Radiance from the environment along a direction: the background with the sky_sphere's
    // layers over it (POV-Ray 3.7's sky).
    // With a world node graph (Blender), its emission for a ray in `state`.
    Color environment(const Vec3& dir) const;
    Color environment(const Vec3& dir, const shader::RayState& state) const;
    // A node graph's closures at `hit` for a ray along `dir` in `state`, into `set` (the
    // BSDFs), with the emission, transparency; false when the material has no graph.
    void graph_closures(const PathMaterial& row, const Hit& hit, const Vec3& dir,
                        const shader::RayState& state, shader::ClosureList* out) const;
    // The normal a subsurface walk leaves `hit` with (seen along `dir`, towards the surface):
    // the BSSRDFs' bumped normals where the material's graph has them (bump's footprint that
    // of a ray `travelled` long), else the smooth one; on the outside.
    Vec3 subsurface_exit_normal(const PathMaterial* row, const Hit& hit, const Vec3& dir,
                                double travelled) const;
    // The objects a ray is inside, innermost last (POV-Ray's interiors, Cycles' volume stack),
    // and which of them hold a medium; bounded so that paths stay allocation-free.
    struct MediumStack {
        static constexpr int kMax = 8;
        int object[kMax];
        int medium[kMax];  // media_ index, -1: none
        bool hollow[kMax];
        double step[kMax];  // ray-marching step of a medium that varies in space, else inf
        int count = 0;
        // The ray leaves `hit`'s surface along `dir`: enters or leaves its object.
        void cross(const Hit& hit, const Vec3& dir, const PathIntegrator& pi);
    };
    // The media acting on a ray in `stack`: the objects' own, and the world's (POV-Ray's
    // atmosphere) while every object the ray is in is hollow; and the smallest ray-marching
    // step among them (kInfinity when none varies in space).
    struct ActiveMedium {
        const PathMedium* medium;
        int object;
    };
    int active_media(const MediumStack& stack, ActiveMedium* out, double* step) const;
    void medium_at(const ActiveMedium* media, int n, const Vec3& p, const Vec3& dir,
                   MediumPoint* out) const;
    // The random numbers of a path's media: as many as their collisions need, drawn in
    // turn from the sampler's pairs from `base` on.
    struct VolumeRandom {
        const PixelSampler* sampler;
        uint32_t base;
        uint32_t draws = 0;
        double operator()() {
            const Sample2 s = sampler->get2(base + draws / 2);
            return (draws++ & 1) ? s.v : s.u;
        }
    };
    // Carries a path through the media on a segment of length `tmax` (kInfinity: open):
    // returns 0 when it gets through (beta weighted), 1 when it scatters at *t (the medium
    // there in *mp), 2 when it is absorbed; `emitted` receives the media's emission on the
    // way, times the throughput.
    int track(const ActiveMedium* act, int na, const Ray& r, double tmax,
              VolumeRandom& random, Color* beta, Color* emitted, double* t,
              MediumPoint* mp) const;
    // Cycles' ray marching through media that vary in space (volume_integrate_heterogeneous):
    // steps of `step`, each shaded once at a random offset and taken as homogeneous.
    int march(const ActiveMedium* act, int na, double step, const Ray& r, double tmax,
              VolumeRandom& random, Color* beta, Color* emitted, double* t,
              MediumPoint* mp) const;
    // The direct light of point-like lights scattered along a homogeneous segment, by
    // equiangular sampling (one distance per light, MIS against distance sampling's pdf for
    // throughput `beta0`); the lights chosen as next-event estimation chooses them.
    Color equiangular_direct(const ActiveMedium* act, int na, const Ray& r, double tmax,
                             const Color& beta0, const MediumStack& stack,
                             const PixelSampler& sampler, uint32_t base, VolumeRandom& random,
                             uint64_t* rays) const;
    // The density with which homogeneous tracking (track) picks the scattering distance t
    // for throughput `beta0` in the medium `m`.
    static double distance_pdf(const Color& beta0, const MediumPoint& m, double t);
    // A medium's ray-marching step in `object` (Cycles' Object::compute_volume_step_size).
    double volume_step(int object, int material) const;
    // The step of a world volume that varies in space (Cycles' background volume_step_size).
    double world_volume_step() const;
    // Whether a camera ray starts where the camera is (then it is inside the volumes that
    // hold the camera): at its location, or moved straight ahead from it by the clip start.
    bool starts_at_camera(const Ray& r) const;
    // Light passing from `origin` along `dir` for `dist`: through alpha holes and
    // index-matched (IOR 1) transmissive surfaces, tinted, and through the media on the way;
    // any other surface blocks it; at the path's shutter time. `stack` holds the media at
    // the origin; `seed` feeds the ratio tracking of media that are not homogeneous.
    Color transmittance(const Vec3& origin, const Vec3& dir, double dist, double time,
                        MediumStack stack, uint32_t seed, uint64_t* rays) const;
    // Transmittance of the media over [0, dist] along a ray (exp(-sigma_t d) where they are
    // homogeneous, ratio tracking where not).
    Color media_transmittance(const ActiveMedium* media, int n, double step, const Vec3& origin,
                              const Vec3& dir, double dist, uint32_t* seed) const;

    const scene::Scene& scene_;
    const Geometry& geometry_;
    const MaterialTable& materials_;
    const shader::GraphShading* graphs_;
    // The world graph's emission where it is the same in every direction and for every ray
    // (a plain colour): evaluated once instead of at every escaped ray and world sample.
    std::optional<Color> world_constant_;
    PigmentEvaluator pigments_;
    PathSettings settings_;
    std::optional<PathLights> lights_;
    // Media: one per material whose interior holds any, and the world's.
    std::vector<PathMedium> media_;
    std::vector<int> material_medium_;  // per material: media_ index or -1
    // Per material: its medium inside Volume objects (grids), where that differs; else -1.
    std::vector<int> material_grid_medium_;
    std::vector<double> object_size_;   // per object: the mean side of its world bounds
    int world_medium_ = -1;
    double world_step_ = kInfinity;  // its ray-marching step, where it varies in space
    // mm_per_unit where POV-Ray's subsurface light transport is on, else 0.
    double sslt_mm_ = 0;
    bool has_media_ = false;
    MediumStack camera_stack_;
    mutable std::atomic<uint64_t> nonfinite_{0};
    // One counter per worker thread, each on its own cache line: a shared one, added to after
    // every sample by every thread, bounced its line between the cores.
    struct alignas(64) RayCount {
        std::atomic<uint64_t> n{0};
    };
    mutable std::vector<RayCount> rays_;
};

}  // namespace glint::render
