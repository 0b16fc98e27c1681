#include "render/integrators/whitted.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>

#include "core/float.h"
#include "render/lights/blender_lights.h"
#include "render/lights/area_light.h"
#include "render/lights/sky.h"
#include "render/materials/sslt_scene.h"
#include "render/prepare/containing.h"
#include "render/shapes/primitive.h"
#include "render/textures/normal.h"

namespace glint::render {
namespace {

// The shadow cache of one thread: what blocked the last shadow ray towards each light, for
// the integrator whose serial it holds.
struct ShadowCache {
    uint64_t serial = 0;
    std::vector<int> blocker;
};

uint64_t next_serial() {
    static std::atomic<uint64_t> counter{0};
    return ++counter;
}

// Shadow rays end this fraction short of the light so the light's own position never counts.
constexpr double kShadowEnd = 1.0 - 1.0e-9;
// POV-Ray's SHADOW_TOLERANCE: the shortest rest of a shadow ray that media still act on.
constexpr double kShadowTolerance = 1.0e-3;

using scene::ColorFT;

// POV-Ray's greyscale weights (base/types.h RED/GREEN/BLUE_INTENSITY).
double greyscale(const Color& c) { return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b; }

// Light that passes a layer: rgb * filter + transmit (Colour::rgbTransm).
Color rgb_transm(const ColorFT& c) {
    return Color(c.rgb.r * c.filter + c.transmit, c.rgb.g * c.filter + c.transmit,
                 c.rgb.b * c.filter + c.transmit);
}

// The texture a ray sees where it meets a surface of `mat`, from inside or from outside.
const scene::Texture& side_texture(const scene::Material& mat, bool from_inside) {
    return from_inside && !mat.interior_texture.empty() ? mat.interior_texture[0] : mat.texture;
}

// `raw_normal`: the surface normal facing the ray (the slope pattern's), `dir` the ray's
// direction (the aoi pattern's), both kept alive by the caller.
PatternPoint pattern_point(const Hit& hit, const scene::Material& mat, const Vec3& raw_normal,
                           const Vec3& dir) {
    return texture_point({hit.p, hit.uv, hit.has_uv, &raw_normal, &dir}, mat.uv_points);
}

// A blend's textures below adc_bailout are skipped (ComputeTextureColour); entries of the same
// texture (a blob's untextured components share the blob's) light alike, so each is lit once
// with their summed weight.
void merge_blend(std::vector<TextureWeight>* blend, double adc) {
    size_t n = 0;
    for (size_t i = 0; i < blend->size(); ++i) {
        const TextureWeight w = (*blend)[i];
        if (w.weight < adc) continue;
        size_t j = 0;
        while (j < n && (*blend)[j].material != w.material) ++j;
        if (j < n) (*blend)[j].weight += w.weight;
        else (*blend)[n++] = w;
    }
    blend->resize(n);
}

}  // namespace

bool Whitted::Interiors::contains(int obj, int id) const {
    for (int i = 0; i < count; ++i)
        if (object[i] == obj && interior[i] == id) return true;
    return false;
}

bool Whitted::Interiors::remove(int obj, int id) {
    for (int i = count - 1; i >= 0; --i) {
        if (object[i] == obj && interior[i] == id) {
            for (int j = i; j + 1 < count; ++j) {
                object[j] = object[j + 1];
                interior[j] = interior[j + 1];
                ior[j] = ior[j + 1];
                material[j] = material[j + 1];
                hollow[j] = hollow[j + 1];
            }
            --count;
            return true;
        }
    }
    return false;
}

void Whitted::Interiors::append(int obj, int id, double value, int mat, bool is_hollow) {
    if (count == kMax) return;  // deeper nesting than any sane scene: ignore the innermost
    object[count] = obj;
    interior[count] = id;
    ior[count] = value;
    material[count] = mat;
    hollow[count] = is_hollow;
    ++count;
}

Whitted::Whitted(const PreparedScene& prepared)
    : scene_(prepared.scene),
      features_(prepared.features),
      geometry_(*prepared.geometry),
      projected_(prepared.projected_through),
      materials_(prepared.materials),
      pigments_(prepared.textures.get(),
                PatternContext{scene_.global.noise_generator, scene_.global.number_of_waves,
                               &scene_.functions, prepared.pattern_objects.get()}),
      atmosphere_(scene_),
      lights_(prepare_lights(whitted_lights(scene_.lights))),
      media_(scene_, whitted_lights(scene_.lights), &pigments_),
      max_level_(scene_.global.max_trace_level),
      adc_bailout_(scene_.global.adc_bailout),
      legacy_(scene_.version < 3.7),
      serial_(next_serial()) {
    for (const scene::Media& m : scene_.media) atmosphere_media_.push_back(&m);
    if (features_.secondary_rays() || features_.media) find_camera_interiors();
    if (scene_.global.radiosity)
        radiosity_ = std::make_unique<Radiosity>(*scene_.global.radiosity, scene_.camera.location);
}

Whitted::~Whitted() = default;

void Whitted::find_camera_interiors() {
    // Only refraction, interior fading and media care which objects contain the eye.
    for (const Containing& c : objects_containing_camera(scene_, geometry_)) {
        const int id = interior_id(c.material);
        if (!camera_interiors_.contains(c.object, id))
            camera_interiors_.append(c.object, id, scene_.materials[c.material].interior.ior,
                                     c.material, c.hollow);
    }
}

Color Whitted::li(const Ray& ray, RadiosityTicket* ticket) const {
    RayState state;
    state.primary = true;
    state.max_level = max_level_;
    state.adc = adc_bailout_;
    if (radiosity_ && ticket && ticket->block) state.rad = ticket;
    if (camera_interiors_.count > 0 && ray.origin == scene_.camera.location)
        state.interiors = camera_interiors_;
    return trace(ray, 1.0, state, false);
}

bool Whitted::find_hit(const Ray& ray, const RayState& state, Hit* hit) const {
    // NoSomethingFlagRayObjectCondition: image rays skip no_image objects, reflection rays
    // skip no_reflection ones. Skipped surfaces are stepped over.
    uint32_t skip = 0;
    if (state.image_ray()) skip |= kNoImage;
    if (state.reflection) skip |= kNoReflection;
    if (state.radiosity) skip |= kNoRadiosity;
    Ray r = ray;
    double travelled = 0;
    for (int i = 0; i < 64; ++i) {
        if (!geometry_.intersect(r, hit)) return false;
        if (!(hit->flags & skip)) {
            hit->t += travelled;
            return true;
        }
        Vec3 origin = offset_ray_origin(hit->p, hit->p_error, hit->ng, r.dir);
        travelled += length(origin - r.origin) / length(r.dir);
        r.tmax = r.tmax - hit->t;
        r.origin = origin;
        if (!(r.tmax > 0)) return false;
    }
    return false;
}

Color Whitted::trace(const Ray& ray, double weight, const RayState& in, bool continued,
                     double* depth_out) const {
    // TraceRay: max_trace_level and adc_bailout end the recursion with black.
    if (depth_out) *depth_out = kInfinity;
    if (in.level >= in.max_level || weight < in.adc) return Color();
    Hit hit;
    bool found = find_hit(ray, in, &hit);
    const double len = length(ray.dir);
    if (depth_out && found) *depth_out = hit.t * len;
    if (in.rad && in.rad->importance_queried >= 0) {
        // A radiosity sample ray past its share gives up on objects of lower importance.
        double importance = scene_.global.radiosity_importance;
        if (found && scene_.objects[static_cast<size_t>(hit.object)].radiosity_importance >= 0)
            importance = scene_.objects[static_cast<size_t>(hit.object)].radiosity_importance;
        in.rad->importance_found = importance;
        if (importance < in.rad->importance_queried) return Color();
        in.rad->importance_queried = -1;  // rays traced on from here do not ask
    }
    RayState state = in;
    if (!continued) ++state.level;
    Color c = found ? shade(ray, hit, weight, state) : sky(ray.dir);
    if (!features_.media && atmosphere_.empty()) return c;
    // Radiosity's rays see no media, fog or rainbow unless its `media on` (POV-Ray clears
    // Q_VOLUME for them).
    if (in.radiosity && !radiosity_->settings().media) return c;
    const Vec3 dir = ray.dir / len;
    const double depth = found ? hit.t * len : Atmosphere::kMissDepth;
    auto light = [&](size_t l, const Vec3& p, Color* lc, Vec3* ld) {
        return media_light(l, p, in.interiors, lc, ld);
    };
    // ComputeTextureColour: the media of the hollow objects the ray is inside, from its
    // origin to the surface.
    if (found && features_.media && in.interiors.count > 0 && hollow(in)) {
        std::vector<const scene::Media*> media;
        interior_media(in.interiors, &media);
        media_.compute(media, ray.origin, dir, depth, false, light, &c, nullptr);
    }
    // Rainbow, atmospheric media and fog act on rays through open space (Ray::IsHollowRay:
    // every object the ray is inside of is hollow), in TraceRay's order.
    if (hollow(in)) {
        c = atmosphere_.apply_rainbow(dir, depth, c);
        media_.compute(atmosphere_media_, ray.origin, dir, depth, false, light, &c, nullptr);
        c = atmosphere_.apply_fog(ray.origin, dir, depth, c);
    }
    return c;
}

void Whitted::interior_media(const Interiors& in, std::vector<const scene::Media*>* out) const {
    for (int i = 0; i < in.count; ++i) {
        const int m = in.material[i];
        if (m < 0 || m >= static_cast<int>(scene_.materials.size())) continue;
        for (const scene::Media& md : scene_.materials[m].interior.media) out->push_back(&md);
    }
}

bool Whitted::media_light(size_t light_index, const Vec3& p, const Interiors& eye, Color* out,
                          Vec3* dir) const {
    // TestShadow: the light's attenuated colour, through whatever lies towards it.
    const PreparedLight& light = lights_[light_index];
    LightSample ls;
    if (!light.sample(p, &ls)) return false;
    Color lc = ls.color;
    auto dark = [](const Color& c) {
        return std::fabs(c.r) < kPovEpsilon && std::fabs(c.g) < kPovEpsilon &&
               std::fabs(c.b) < kPovEpsilon;
    };
    if (dark(lc)) return false;
    if (features_.shadows && light.casts_shadows()) {
        if (light.light().area) {
            lc = area_light_shadow(light, p, lc, [&](const Vec3& d, double depth, const Color& c) {
                return shadow_walk(p, p + d * depth, d, c, eye, light_index, photons_ != nullptr);
            });
        } else {
            lc = shadow_walk(p, p + ls.dir * ls.distance, ls.dir, lc, eye, light_index,
                             photons_ != nullptr);
        }
        if (dark(lc)) return false;
    }
    *out = lc;
    *dir = ls.dir;
    return true;
}

bool Whitted::hollow(const Interiors& in) const {
    for (int i = 0; i < in.count; ++i)
        if (!in.hollow[i]) return false;
    return true;
}

Color Whitted::fade(const scene::Interior& interior, double depth) const {
    // ComputeLightedTexture: fade_power >= 1000 means exponential attenuation.
    if (interior.fade_power >= 1000) {
        double d = depth / interior.fade_distance;
        return Color(std::exp(-(1.0 - interior.fade_color.r) * d),
                     std::exp(-(1.0 - interior.fade_color.g) * d),
                     std::exp(-(1.0 - interior.fade_color.b) * d));
    }
    double att = 1.0 + std::pow(depth / interior.fade_distance, interior.fade_power);
    return interior.fade_color + (Color(1.0) - interior.fade_color) / att;
}

double Whitted::relative_ior(const RayState& state, int object, int interior,
                             double ior) const {
    // ComputeRelativeIOR (used by fresnel reflection).
    const Interiors& in = state.interiors;
    if (in.count == 0) return ior;
    if (in.contains(object, interior)) {
        if (in.count == 1) return 1.0 / ior;
        return in.ior[in.count - 1] / ior;
    }
    return ior / in.ior[in.count - 1];
}

Color Whitted::shade(const Ray& ray, const Hit& hit, double weight, const RayState& state) const {
    if (hit.material < 0 || hit.material >= static_cast<int>(scene_.materials.size()))
        return Color();
    const scene::Material& mat = scene_.materials[hit.material];
    // ComputeTextureColour: the normal faces the incoming ray; a ray that meets the surface
    // from inside (the outward normal faces away from it) sees the interior_texture.
    Vec3 n = hit.n;
    const bool from_inside = dot(n, ray.dir) > 0.0;
    if (from_inside) n = -n;
    TextureStack stack;
    std::vector<TextureWeight> blend;
    if (hit.blend_source && hit.blend_source->texture_blend(hit.blend_point, &blend)) {
        // A blob with component textures: each one is lit on its own and the colours mixed
        // by weight (interior_texture does not apply).
        merge_blend(&blend, state.adc);
        const PatternPoint at = pattern_point(hit, mat, n, ray.dir);
        Color sum;
        for (const TextureWeight& w : blend) {
            const scene::Texture& tex =
                w.material >= 0 ? scene_.materials[w.material].texture : mat.texture;
            sum += texture_colour(ray, hit, tex, at, n, weight, state, stack) * w.weight;
        }
        return sum;
    }
    return texture_colour(ray, hit, side_texture(mat, from_inside),
                          pattern_point(hit, mat, n, ray.dir), n, weight, state, stack);
}

Color Whitted::lighted_texture(const Ray& ray, const Hit& hit, const scene::Texture& tex,
                               const PatternPoint& at, const Vec3& n, double weight,
                               const RayState& state, const TextureStack& stack) const {
    const scene::Material& mat = scene_.materials[hit.material];
    // ComputeLightedTexture: layers from the top one down; each adds its own light, seen
    // through the filter of the layers above it, until too little shows through.
    const int layer_count = 1 + static_cast<int>(tex.layers.size());
    auto layer_at = [&](int i) -> const scene::Texture& {  // 0 = top
        return i == layer_count - 1 ? tex : tex.layers[layer_count - 2 - i];
    };
    LayerReflection refl[kMaxLayers];
    int used = 0;

    Color result;
    Color fil_col(1.0);
    double trans = 1.0;
    bool one_colour_found = false;
    Vec3 top_normal = n;
    const bool double_illuminate = (hit.flags & kDoubleIlluminate) != 0;
    // Radiosity's indirect light, once per hit (the first layer that can show enough of it).
    const bool radiosity_needed = state.rad && radiosity_->recurses(*state.rad);
    bool radiosity_done[2] = {false, false};  // the near side; the far side (diffuse_back)
    Color ambient_light[2];
    // The photons around the hit, gathered once (for the first layer that asks).
    PhotonGather gathered;
    const bool collects = photons_ && photons_->size() > 0 &&
                          scene_.objects[static_cast<size_t>(hit.object)].photon_collect;
    for (int li = 0; li < layer_count && trans > state.adc; ++li) {
        const scene::Texture& layer = layer_at(li);
        const ClassicFinish& f = materials_.classic_finish(layer.finish, hit.material);
        const Vec3 lay_n = layer_normal(layer.normal, at, n, stack);
        if (li == 0) top_normal = lay_n;
        const double new_weight = weight * trans;
        ColorFT pig;
        const bool colour_found = pigments_.evaluate(layer.pigment, at, &pig);
        one_colour_found = one_colour_found || colour_found;

        double refl_weight = new_weight;
        const double cos_incidence = -dot(ray.dir, lay_n);
        Color reflec = f.reflects()
                           ? reflectivity(f, cos_incidence,
                                          relative_ior(state, hit.object, interior_id(hit.material), mat.interior.ior),
                                          &refl_weight)
                           : Color();
        if (f.reflect_metallic != 0.0)
            reflec = metallic_tint(f.reflect_metallic, cos_incidence, pig.rgb, reflec);
        if (used < kMaxLayers) refl[used++] = {refl_weight, lay_n, reflec, f.reflect_exponent, &f};

        // The layer's own brightness is reduced by its transparency; 3.6 scenes keep the old
        // (bogus, but compatible) formula.
        const double att = legacy_ ? 1.0 - (pig.filter * pig.rgb.max() + pig.transmit)
                                   : 1.0 - pig.filter - pig.transmit;
        // Subsurface light transport stands in for the diffuse term (POV-Ray keeps no
        // diffuse beside it: a surface-only diffuse is a layer of its own).
        // Radiosity's rays see subsurface finishes as plain ones unless its `subsurface on`.
        const bool sslt = f.subsurface && scene_.global.subsurface &&
                          !(state.radiosity && !radiosity_->settings().subsurface);
        Color tmp;
        if (sslt && features_.lights) {
            Vec3 raw_n = hit.n;
            if (dot(raw_n, ray.dir) > 0) raw_n = -raw_n;
            tmp = subsurface(f, pig.rgb, ray, hit, raw_n, state);
        }
        // Indirect light on the near side and, for diffuse backside illumination, on the far
        // side, the normals flipped (ComputeLightedTexture).
        for (int side = 0; radiosity_needed && side < 2; ++side) {
            const double d = side ? f.diffuse_back : f.diffuse;
            if (side && d == 0.0) break;
            const double most = greyscale(fil_col * pig.rgb) * att * d;
            if (!radiosity_done[side] && most > state.adc) {
                const double s = side ? -1.0 : 1.0;
                ambient_light[side] =
                    radiosity_ambient(hit, n * s, lay_n * s, weight * most, state);
                radiosity_done[side] = true;
            }
            tmp += pig.rgb * ambient_light[side] * (att * d);
        }
        // 3.7 scenes with radiosity keep `ambient` out: radiosity is their ambient light.
        if (!radiosity_ || legacy_) tmp += pig.rgb * f.ambient * scene_.global.ambient_light * att;
        tmp += pig.rgb * f.emission * att;
        // A pretrace camera ray only feeds the cache: no direct light.
        const bool lit = !(state.rad && state.rad->pretrace && !state.radiosity);
        if (lit && features_.lights &&
            (f.diffuse != 0.0 || f.diffuse_back != 0.0 || f.specular != 0.0 || f.phong != 0.0)) {
            for (size_t light_index = 0; light_index < lights_.size(); ++light_index) {
                const PreparedLight& light = lights_[light_index];
                if (!light.lights_object(hit.flags)) continue;
                LightSample ls;
                if (!light.sample(hit.p, &ls)) continue;
                // Blender lights: Cycles' falloff, from the centre (blender_lights.h).
                if (light.light().blender &&
                    !whitted_blender_color(light.light(), hit.p, &ls.color))
                    continue;
                // Light on the far side of the surface from the viewer: only diffuse_back.
                const bool backside = !double_illuminate && dot(lay_n, ls.dir) < kPovEpsilon;
                if (backside && f.diffuse_back == 0.0) continue;
                Color lc = ls.color;
                if (features_.shadows && light.casts_shadows()) {
                    // Radiosity's rays see area lights as point lights (no Q_AREA_LIGHT).
                    if (light.light().area && !state.radiosity) {
                        lc = area_light_shadow(
                            light, hit.p, lc, [&](const Vec3& d, double depth, const Color& c) {
                                return shadow_filter(hit.p, hit, LightSample{d, depth, c},
                                                     state, light_index);
                            });
                    } else {
                        lc = shadow_filter(hit.p, hit, ls, state, light_index);
                    }
                    if (!(std::fabs(lc.r) > kPovEpsilon || std::fabs(lc.g) > kPovEpsilon ||
                          std::fabs(lc.b) > kPovEpsilon))
                        continue;
                } else if (light_index < projected_.size() && projected_[light_index]) {
                    // A shadowless light still passes only through its projected_through.
                    Vec3 end;
                    if (!projected_end(light_index,
                                       offset_ray_origin(hit.p, hit.p_error, hit.ng, ls.dir),
                                       hit.p + ls.dir * ls.distance, &end))
                        continue;
                }
                Color one;
                if (!sslt) one += diffuse_term(f, lay_n, ls.dir, pig.rgb, lc, att, backside);
                // shadowless lights are POV-Ray's FILL_LIGHT_SOURCE: diffuse only; and
                // radiosity's rays and the backside see no highlights.
                if (light.casts_shadows() && !state.radiosity && !backside) {
                    if (f.phong > 0.0) one += phong_term(f, lay_n, ls.dir, ray.dir, pig.rgb, lc);
                    if (f.specular > 0.0)
                        one += specular_term(f, lay_n, ls.dir, ray.dir, pig.rgb, lc);
                }
                if (f.irid > 0.0)
                    one *= irid_factor(f, ls.dir, ray.dir, lay_n, hit.p,
                                       scene_.global.irid_wavelength,
                                       scene_.global.noise_generator);
                tmp += one;
            }
        }
        if (collects)
            tmp += photon_light(f, hit, ray, lay_n, n, pig.rgb, att, !state.radiosity, &gathered);
        result += tmp * fil_col;

        // New filter color and remaining translucency.
        if (colour_found) {
            fil_col *= rgb_transm(pig);
            if (f.conserve_energy && f.reflects()) {
                fil_col *= Color(std::min(1.0, 1.0 - reflec.r), std::min(1.0, 1.0 - reflec.g),
                                 std::min(1.0, 1.0 - reflec.b));
            }
        }
        trans = std::min(1.0, std::fabs(greyscale(fil_col)));
    }

    bool tir = false;
    if (trans > state.adc && features_.secondary_rays()) {
        double w1 = std::max(std::fabs(fil_col.r), std::max(std::fabs(fil_col.g),
                                                            std::fabs(fil_col.b)));
        Color rfr;
        tir = refract(ray, hit, top_normal, n, weight * w1, state, &rfr);
        const scene::Interior& interior = mat.interior;
        Color att_col(interior.old_refraction);
        if (state.interiors.contains(hit.object, interior_id(hit.material)) &&
            std::fabs(interior.fade_distance) > kPovEpsilon)
            att_col *= fade(interior, hit.t);
        if (tir || !one_colour_found)
            result += att_col * rfr;
        else
            result += att_col * rfr * fil_col;
    }

    // Reflection per layer, with that layer's normal; after total internal reflection the
    // mirror ray about the top normal was already traced.
    for (int i = 0; i < used; ++i) {
        const LayerReflection& r = refl[i];
        if (tir && std::fabs(top_normal.x - r.normal.x) <= kPovEpsilon &&
            std::fabs(top_normal.y - r.normal.y) <= kPovEpsilon &&
            std::fabs(top_normal.z - r.normal.z) <= kPovEpsilon)
            continue;
        if (r.reflec.is_black()) continue;
        Color rfl = reflect(ray, hit, r.normal, n, r.weight, state);
        if (r.finish->irid > 0.0)
            rfl *= irid_factor(*r.finish, reflected_direction(ray.dir, r.normal, n), ray.dir,
                               r.normal, hit.p, scene_.global.irid_wavelength,
                               scene_.global.noise_generator);
        if (r.exponent != 1.0) {
            rfl = Color(std::pow(rfl.r, r.exponent), std::pow(rfl.g, r.exponent),
                        std::pow(rfl.b, r.exponent));
        }
        result += r.reflec * rfl;
    }
    return result;
}

Color Whitted::radiosity_ambient(const Hit& hit, const Vec3& raw_n, const Vec3& lay_n,
                                 double weight, const RayState& state) const {
    // The sample rays are new rays (RadiosityFunction::GatherLight): no interiors, not image
    // rays, restarted at the depth's trace level with radiosity's adc_bailout.
    auto trace_sample = [&](const Ray& r, double w, int level, RadiosityTicket& ticket,
                            double* depth) {
        RayState next;
        next.level = level;
        next.max_level = std::max(state.max_level, level + 1);
        next.adc = radiosity_->settings().adc_bailout;
        next.radiosity = true;
        next.rad = &ticket;
        return trace(r, w, next, false, depth);
    };
    const RadiosityPoint at{hit.p, hit.p_error, hit.ng, raw_n, lay_n};
    return radiosity_->ambient(at, weight, *state.rad, trace_sample);
}

Color Whitted::subsurface(const ClassicFinish& f, const Color& pigment, const Ray& ray,
                          const Hit& out, const Vec3& raw_n, const RayState& state) const {
    if (state.subsurface_depth >= 2) return Color();
    RayState inner = state;
    ++inner.subsurface_depth;
    const scene::GlobalSettings& g = scene_.global;
    SsltSettings s;
    s.samples_diffuse = state.subsurface_depth == 1 ? 1 : g.subsurface_samples_diffuse;
    s.samples_single = state.subsurface_depth == 1 ? 1 : g.subsurface_samples_single;
    s.mm_per_unit = g.mm_per_unit;
    s.adc_bailout = adc_bailout_;
    const CallbackSsltScene view(
        geometry_, lights_, features_.shadows,
        [&](size_t k, const Hit& at, const LightSample& ls) {
            return shadow_filter(at.p, at, ls, inner, k);
        },
        [&](const Ray& r, double weight) {
            RayState next = inner;
            next.primary = false;
            next.refraction = true;
            return trace(r, weight, next, false);
        });
    const double ior = scene_.materials[static_cast<size_t>(out.material)].interior.ior;
    return subsurface_light(view, s, f.translucency, pigment * f.diffuse,
                            relative_ior(state, out.object, interior_id(out.material), ior), ray, out, raw_n);
}

Vec3 reflected_direction(const Vec3& dir, const Vec3& n, const Vec3& raw_n) {
    // ComputeReflection: mirror about the (perturbed) normal; a mirror ray that would enter
    // the surface is corrected with the raw normal.
    Vec3 d = dir + n * (-2.0 * dot(dir, n));
    if (dot(d, raw_n) < 0.0) {
        if (dot(d, n) < 0.0)
            d = dir + raw_n * (-2.0 * dot(dir, raw_n));
        else
            d = d + raw_n * (-2.0 * dot(d, raw_n));
    }
    return normalize(d);
}

Color Whitted::reflect(const Ray& ray, const Hit& hit, const Vec3& n, const Vec3& raw_n,
                       double weight, const RayState& state) const {
    const Vec3 d = reflected_direction(ray.dir, n, raw_n);
    Ray r;
    r.dir = d;
    r.origin = offset_ray_origin(hit.p, hit.p_error, hit.ng, d);
    RayState next = state;
    next.primary = false;
    next.reflection = true;  // SetFlags(ReflectionRay, ray): refraction flag is kept
    return trace(r, weight, next, false);
}

double Whitted::cross_interface(const Hit& hit, Interiors* in) const {
    // ComputeRefraction: relative ior from the interiors the ray traverses; nested objects
    // count as outside their container, overlaps belong to the last one entered.
    const double ior_obj = scene_.materials[hit.material].interior.ior;
    const int id = interior_id(hit.material);
    if (in->count == 0) {
        in->append(hit.object, id, ior_obj, hit.material, (hit.flags & kHollow) != 0);
        return 1.0 / ior_obj;
    }
    if (in->object[in->count - 1] == hit.object && in->interior[in->count - 1] == id) {
        in->remove(hit.object, id);
        return in->count == 0 ? ior_obj : ior_obj / in->ior[in->count - 1];
    }
    if (in->remove(hit.object, id)) return 1.0;
    const double ior = in->ior[in->count - 1] / ior_obj;
    in->append(hit.object, id, ior_obj, hit.material, (hit.flags & kHollow) != 0);
    return ior;
}

bool refracted_direction(const Vec3& dir, const Vec3& n, double ior, Vec3* out) {
    // TraceRefractionRay (Heckbert's method) with the normal turned against the ray (a
    // perturbed normal may not be); false on total internal reflection.
    double c = dot(dir, n);
    Vec3 local_n = n;
    if (c <= 0.0) {
        c = -c;
    } else {
        local_n = -n;
    }
    double t = 1.0 + ior * ior * (c * c - 1.0);
    if (t < 0.0) return false;
    t = ior * c - std::sqrt(t);
    *out = normalize(dir * ior + local_n * t);
    return true;
}

bool Whitted::refract(const Ray& ray, const Hit& hit, const Vec3& n, const Vec3& raw_n,
                      double weight, const RayState& state, Color* out) const {
    RayState next = state;
    next.primary = false;
    next.refraction = true;  // SetFlags(RefractionRay, ray): reflection flag is kept
    const double ior = cross_interface(hit, &next.interiors);
    Ray r;
    if (std::fabs(ior - 1.0) < kPovEpsilon) {
        // Same medium on both sides: the ray continues without counting a trace level.
        r.dir = ray.dir;
        r.origin = offset_ray_origin(hit.p, hit.p_error, hit.ng, r.dir);
        *out = trace(r, weight, next, true);
        return false;
    }
    if (!refracted_direction(ray.dir, n, ior, &r.dir)) {
        *out = reflect(ray, hit, n, raw_n, weight, state);
        return true;
    }
    r.origin = offset_ray_origin(hit.p, hit.p_error, hit.ng, r.dir);
    *out = trace(r, weight, next, false);
    return false;
}

Color Whitted::shadow_filter(const Vec3& p, const Hit& at, const LightSample& ls,
                             const RayState& eye, size_t light) const {
    const bool collects =
        photons_ && scene_.objects[static_cast<size_t>(at.object)].photon_collect;
    return shadow_walk(offset_ray_origin(p, at.p_error, at.ng, ls.dir), p + ls.dir * ls.distance,
                       ls.dir, ls.color, eye.interiors, light, collects);
}

bool Whitted::projected_end(size_t light, const Vec3& origin, const Vec3& target,
                            Vec3* end) const {
    *end = target;
    if (light >= projected_.size() || !projected_[light]) return true;
    Ray r;
    r.origin = origin;
    r.dir = target - origin;
    r.tmax = kShadowEnd;
    LocalHit h;
    if (!projected_[light]->intersect(r, r.tmax, false, &h)) return false;
    const double len = length(r.dir);
    *end = origin + r.dir * (std::max(0.0, h.t * len - kShadowTolerance) / len);
    return true;
}

Color Whitted::shadow_walk(const Vec3& origin, const Vec3& light_target, const Vec3& light_dir,
                           const Color& light_colour, const Interiors& eye, size_t light,
                           bool collects) const {
    // TracePointLightShadowRay's projected_through test: only what lies before the object
    // can shadow the light, and a ray that misses the object gets none.
    Vec3 target;
    if (!projected_end(light, origin, light_target, &target)) return Color();
    Ray r;
    r.origin = origin;
    r.dir = target - r.origin;
    r.tmax = kShadowEnd;
    // Per thread, per light: the object that blocked the last shadow ray, tried first
    // (neighbouring pixels and an area light's samples are mostly blocked by the same
    // one). The answer does not depend on it, so neither does the image.
    thread_local ShadowCache cache;
    if (cache.serial != serial_) {
        cache.serial = serial_;
        cache.blocker.assign(lights_.size(), -1);
    }
    // Media along the way (interior media, or the atmosphere's media and fog for a light with
    // media_attenuation) need the walk even where no surface is in the way.
    const bool attenuate = lights_[light].light().media_attenuation &&
                           lights_[light].light().media_interaction &&
                           (!atmosphere_media_.empty() || atmosphere_.has_fog());
    const bool media = attenuate || (features_.media && eye.count > 0);
    if (!features_.transparency && !media)
        return geometry_.occluded(r, &cache.blocker[light]) ? Color() : light_colour;
    // Nothing on the way: the walk below would find no surface either. An opaque object
    // anywhere on the way: it would end in black. Only the rest needs the walk.
    switch (geometry_.shadow_blocker(r, &cache.blocker[light])) {
        case Geometry::Blocker::None:
            if (!media) return light_colour;
            break;
        case Geometry::Blocker::Opaque: return Color();
        case Geometry::Blocker::Other: break;
    }

    // TracePointLightShadowRay: walk through transparent objects, filtering the light. The
    // shadow ray starts with the eye ray's interiors and toggles each object it crosses
    // (ComputeShadowMedia), which decides where interior fading applies.
    Interiors inside = eye;
    Color colour = light_colour;
    std::vector<const scene::Media*> segment_media;
    std::vector<TextureWeight> blend;
    auto no_light = [](size_t, const Vec3&, Color*, Vec3*) { return false; };
    // ComputeShadowMedia: the atmosphere's media over one segment, then the fog where the
    // ray is in open space, when the light asks. (POV-Ray applies the atmosphere's media
    // also inside solid objects on the way, but fog only outside them.)
    auto atmosphere = [&](double depth, const Vec3& dir, bool open) {
        if (!attenuate || (colour.r < kPovEpsilon && colour.g < kPovEpsilon &&
                           colour.b < kPovEpsilon))
            return;
        media_.compute(atmosphere_media_, r.origin, dir, depth, true, no_light, &colour, nullptr);
        if (open) colour = atmosphere_.apply_fog(r.origin, dir, depth, colour);
    };
    for (int i = 0; i < 64; ++i) {
        Hit hit;
        if (!geometry_.intersect(r, &hit)) {
            // The rest of the way to the light, through open space only.
            const double rest = length(r.dir);
            if (rest > kShadowTolerance && hollow(inside)) atmosphere(rest, r.dir / rest, true);
            return colour;
        }
        if (!(hit.flags & kNoShadow)) {
            blend.clear();
            const bool blended = hit.blend_source &&
                                 hit.blend_source->texture_blend(hit.blend_point, &blend);
            bool opaque = materials_.opaque(hit.material);
            if (blended) {  // blob component textures: every one must be opaque
                merge_blend(&blend, adc_bailout_);
                opaque = true;
                for (const TextureWeight& w : blend)
                    opaque = opaque &&
                             materials_.opaque(w.material >= 0 ? w.material : hit.material);
            }
            if (opaque) return Color();
            // Light refracted by a photon target reaches a collecting surface as photons
            // only: the target's shadow is full (ComputeShadowColour).
            if (collects && photons_->size() > 0 &&
                photon_refracts(lights_[light].light(), hit.object))
                return Color();
            // ComputeShadowColour / ComputeShadowTexture.
            const scene::Material& mat = scene_.materials[hit.material];
            // POV-Ray stores interior { caustics C } as the exponent 45 C (Parse_Interior).
            // The normal faces back along the shadow ray before the layers perturb it
            // (ComputeShadowColour), which matters for |n . d| once bumps are added.
            const bool from_inside = dot(hit.n, r.dir) > 0.0;
            const Vec3 facing = from_inside ? -hit.n : hit.n;
            Color filter;
            if (blended) {
                // The component textures' filters, mixed by weight (ComputeShadowColour).
                for (const TextureWeight& w : blend) {
                    const scene::Texture& tex =
                        w.material >= 0 ? scene_.materials[w.material].texture : mat.texture;
                    filter +=
                        shadow_texture(tex, pattern_point(hit, mat, facing, r.dir),
                                       45.0 * mat.interior.caustics, facing, normalize(r.dir)) *
                        w.weight;
                }
            } else {
                filter = shadow_texture(side_texture(mat, from_inside),
                                        pattern_point(hit, mat, facing, r.dir),
                                        45.0 * mat.interior.caustics, facing, normalize(r.dir));
            }
            const scene::Interior& interior = mat.interior;
            const double seg = hit.t * length(r.dir);
            const int id = interior_id(hit.material);
            if (inside.contains(hit.object, id) && interior.fade_power > 0.0 &&
                std::fabs(interior.fade_distance) > kPovEpsilon) {
                filter *= fade(interior, seg);
            }
            // The media of the hollow objects the shadow ray is in, up to this surface.
            if (features_.media && inside.count > 0 && hollow(inside)) {
                segment_media.clear();
                interior_media(inside, &segment_media);
                media_.compute(segment_media, r.origin, r.dir / length(r.dir), seg, true,
                               no_light, &filter, nullptr);
            }
            colour *= filter;
            if (std::fabs(colour.r) < kPovEpsilon && std::fabs(colour.g) < kPovEpsilon &&
                std::fabs(colour.b) < kPovEpsilon)
                return Color();
            atmosphere(seg, r.dir / length(r.dir), hollow(inside));
            if (inside.count == 0 || !inside.remove(hit.object, id))
                inside.append(hit.object, id, interior.ior, hit.material,
                              (hit.flags & kHollow) != 0);
        }
        r.origin = offset_ray_origin(hit.p, hit.p_error, hit.ng, r.dir);
        r.dir = target - r.origin;
        r.tmax = kShadowEnd;
        if (dot(r.dir, light_dir) <= 0.0) return colour;
    }
    return colour;
}

Color Whitted::sky(const Vec3& dir) const { return sky_radiance(scene_, pigments_, dir, legacy_); }

}  // namespace glint::render
