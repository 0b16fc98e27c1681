// The Whitted integrator: POV-Ray 3.7's classic lighting model (trace.cpp TraceRay,
// ComputeLightedTexture, ComputeShadowColour, ComputeReflection/Refraction, ComputeSky) as one
// per-ray function the tile driver calls. Prepared once per render; read-only while rendering.
#pragma once

#include <memory>
#include <vector>

#include "render/gi/photon_map.h"
#include "render/gi/radiosity.h"
#include "render/integrators/atmosphere.h"
#include "render/media/pov_media.h"
#include "render/lights/light.h"
#include "render/prepare/prepared_scene.h"
#include "render/textures/pigment.h"

namespace glint::render {

struct ClassicFinish;

// The refracted direction of unit `dir` through a surface with normal `n` (either side) and
// relative index `ior`; false on total internal reflection.
bool refracted_direction(const Vec3& dir, const Vec3& n, double ior, Vec3* out);
// The mirror direction of `dir` about `n`, turned back out with the raw normal `raw_n` (which
// faces the incoming ray) where a perturbed normal would send it into the surface.
Vec3 reflected_direction(const Vec3& dir, const Vec3& n, const Vec3& raw_n);

class Whitted {
public:
    // `prepared` (made for IntegratorKind::Whitted) must outlive the integrator.
    explicit Whitted(const PreparedScene& prepared);

    ~Whitted();

    // Radiance (in POV-Ray's working color space) arriving along a primary ray. With
    // radiosity, `ticket` names the image block the ray belongs to (Radiosity::final_block,
    // or a pretrace block); without, it may be null.
    Color li(const Ray& ray, RadiosityTicket* ticket = nullptr) const;
    // The scene's radiosity (global_settings radiosity), or null. Its pretrace must run
    // before the final render (render.cpp).
    Radiosity* radiosity() const { return radiosity_.get(); }
    // POV-Ray's photon pass (gi/classic_photons.cpp): shoots photons from every light at every
    // target object and builds the map the render gathers from. Run before the render when
    // the scene has global_settings photons; the same photons whatever `threads` is. With
    // `load_file` the photons come from that file instead; with `save_file` they go to it.
    void shoot_photons(int threads);
    const PhotonMap* photons() const { return photons_.get(); }

private:
    // The photon maps from the photons shot (or loaded), in shooting order.
    void keep_photons(std::vector<Photon> surface, std::vector<Photon> media);
    // The objects a ray is inside, innermost last (POV-Ray's ray interior list); bounded so
    // rays stay allocation-free.
    struct Interiors {
        static constexpr int kMax = 16;
        // An interior is the object's and its scene::Material::interior_id (POV-Ray tells a
        // CSG child's own interior from the one it shares with its parent).
        int object[kMax];
        int interior[kMax];
        double ior[kMax];
        int material[kMax];  // whose interior (its media) the ray is in
        bool hollow[kMax];   // the entered shape is hollow (render/ray.h kHollow)
        int count = 0;
        bool contains(int obj, int id) const;
        bool remove(int obj, int id);
        void append(int obj, int id, double ior, int material, bool hollow);
    };
    // POV-Ray's Ray flags that decide no_image/no_reflection visibility.
    struct RayState {
        bool primary = false;
        bool reflection = false;
        bool refraction = false;
        int level = 0;  // trace level before this ray (POV-Ray's ticket.traceLevel)
        int max_level = 0;   // ticket.maxAllowedTraceLevel
        double adc = 0;      // ticket.adcBailout
        bool radiosity = false;  // a radiosity sample ray or one traced on from it
        RadiosityTicket* rad = nullptr;  // the camera sample's radiosity state, if any
        int subsurface_depth = 0;  // subsurface samples this ray is inside of
        Interiors interiors;
        bool image_ray() const { return primary || (refraction && !reflection); }
    };

    // Photons (gi/classic_photons.cpp): one photon's state, its travel, the surface it meets,
    // and what the gathered photons add to a surface's light.
    struct PhotonPath;
    void photon_trace(const Ray& ray, const Color& light, double weight, int level,
                      const Interiors& in, bool continued, PhotonPath& path) const;
    void photon_surface(const Ray& ray, const Hit& hit, Color light, double weight, int level,
                        const Interiors& in, PhotonPath& path) const;
    // The interior media over the `seg` a photon crossed: they dim its `light` and keep media
    // photons along the way.
    void photon_media(const Ray& ray, double seg, Color* light, int level, const Interiors& in,
                      PhotonPath& path) const;
    Color photon_light(const ClassicFinish& f, const Hit& hit, const Ray& ray, const Vec3& lay_n,
                       const Vec3& raw_n, const Color& pigment, double att, bool highlights,
                       PhotonGather* gathered) const;
    // One texture layer's reflection, kept while its layers are lit and traced after them
    // (POV-Ray's WNRX list), for rays and photons alike; at most kMaxLayers layers.
    struct LayerReflection {
        double weight;
        Vec3 normal;
        Color reflec;
        double exponent;
        const ClassicFinish* finish;  // irid
    };
    static constexpr int kMaxLayers = 16;
    // POV-Ray's InitRayContainerState: the objects the perspective camera sits inside.
    void find_camera_interiors();
    // `depth`, when given, receives the distance to the hit (infinity on a miss).
    Color trace(const Ray& ray, double weight, const RayState& state, bool continued,
                double* depth = nullptr) const;
    // Radiosity's indirect light at a hit (ComputeAmbient), facing `raw_n` / `lay_n`.
    Color radiosity_ambient(const Hit& hit, const Vec3& raw_n, const Vec3& lay_n, double weight,
                            const RayState& state) const;
    bool find_hit(const Ray& ray, const RayState& state, Hit* hit) const;
    Color shade(const Ray& ray, const Hit& hit, double weight, const RayState& state) const;
    // The patterned textures a hit point was routed through (POV-Ray's texture warps list):
    // their transforms carry perturbed normals into and out of their pattern space.
    struct TextureStack {
        static constexpr int kMax = 8;
        const scene::Texture* texture[kMax];
        int count = 0;
    };
    Color texture_colour(const Ray& ray, const Hit& hit, const scene::Texture& tex,
                         const PatternPoint& at, const Vec3& n, double weight,
                         const RayState& state, TextureStack stack) const;
    Color lighted_texture(const Ray& ray, const Hit& hit, const scene::Texture& tex,
                          const PatternPoint& at, const Vec3& n, double weight,
                          const RayState& state, const TextureStack& stack) const;
    Vec3 layer_normal(const scene::Normal& normal, const PatternPoint& at, const Vec3& n,
                      const TextureStack& stack) const;
    // The light a texture lets through (ComputeShadowTexture). `caustics` is the fake-caustics
    // exponent, 45 times the interior's value (0 = off); `raw_normal` and `dir` (the shadow
    // ray, unit) feed it.
    Color shadow_texture(const scene::Texture& tex, const PatternPoint& at, double caustics,
                         const Vec3& raw_normal, const Vec3& dir) const;
    // The light `ls` arriving at `p` past whatever lies towards it; `light` indexes lights_
    // (its shadow cache slot).
    Color shadow_filter(const Vec3& p, const Hit& at, const LightSample& ls,
                        const RayState& eye, size_t light) const;
    // The shadow ray from `origin` to the light at `ls`, through transparent objects and
    // media (TracePointLightShadowRay with ComputeShadowColour and ComputeShadowMedia).
    // `collects`: the lit point gathers photons (targets that refract this light then cast
    // full shadows: their light arrives as photons).
    Color shadow_walk(const Vec3& origin, const Vec3& target, const Vec3& light_dir,
                      const Color& light_colour, const Interiors& eye, size_t light,
                      bool collects = false) const;
    // A light with projected_through reaches `origin` from `target` only along a ray that
    // meets its object: false where it misses; `*end` is where the object is met (less
    // POV-Ray's SMALL_TOLERANCE), the end of what may shadow it. True (end = target) for
    // other lights.
    bool projected_end(size_t light, const Vec3& origin, const Vec3& target, Vec3* end) const;
    // Whether `light`'s photons refract through scene object `object` (a target).
    bool photon_refracts(const scene::Light& light, int object) const;
    // Media: the light reaching a point in a medium (TestShadow), the media of the objects a
    // ray is inside, and the interior media over a segment that ends at a surface.
    bool media_light(size_t light, const Vec3& p, const Interiors& eye, Color* colour,
                     Vec3* dir) const;
    void interior_media(const Interiors& in, std::vector<const scene::Media*>* out) const;
    // `n` is the (perturbed) normal, `raw_n` the surface normal facing the ray.
    Color reflect(const Ray& ray, const Hit& hit, const Vec3& n, const Vec3& raw_n, double weight,
                  const RayState& state) const;
    // The relative ior a ray meets crossing `hit`'s surface, entering or leaving its
    // object in `in` (ComputeRefraction's interior bookkeeping).
    double cross_interface(const Hit& hit, Interiors* in) const;
    // Returns true on total internal reflection.
    bool refract(const Ray& ray, const Hit& hit, const Vec3& n, const Vec3& raw_n, double weight,
                 const RayState& state, Color* out) const;
    Color sky(const Vec3& dir) const;
    bool hollow(const RayState& state) const { return hollow(state.interiors); }
    bool hollow(const Interiors& in) const;
    Color fade(const scene::Interior& interior, double depth) const;
    double relative_ior(const RayState& state, int object, int interior, double ior) const;
    // scene::Material::interior_id of a material (-1 for none).
    int interior_id(int material) const {
        return material >= 0 ? scene_.materials[static_cast<size_t>(material)].interior_id : -1;
    }
    // Subsurface light transport (materials/sslt.h) of finish `f` with `pigment` at `out`,
    // seen along `ray`: it stands in for the diffuse term; `raw_n` faces the ray.
    Color subsurface(const ClassicFinish& f, const Color& pigment, const Ray& ray, const Hit& out,
                     const Vec3& raw_n, const RayState& state) const;
    const scene::Scene& scene_;
    const scene::Features& features_;
    const Geometry& geometry_;
    // Per light, its projected_through object (PreparedScene::projected_through).
    const std::vector<std::unique_ptr<ObjectNode>>& projected_;
    const MaterialTable& materials_;
    PigmentEvaluator pigments_;
    Atmosphere atmosphere_;  // fog and rainbow
    std::vector<PreparedLight> lights_;
    PovMedia media_;
    std::vector<const scene::Media*> atmosphere_media_;
    int max_level_;
    double adc_bailout_;
    bool legacy_;  // #version < 3.7: POV-Ray's 3.6 transparency and sky formulas
    Interiors camera_interiors_;
    std::unique_ptr<Radiosity> radiosity_;
    std::unique_ptr<PhotonMap> photons_;
    std::unique_ptr<PhotonMap> media_photons_;
    // Names this integrator's slots in each thread's shadow cache (whitted.cpp).
    uint64_t serial_;
};

}  // namespace glint::render
