// The classic renderer's photon pass: POV-Ray 3.7's photon shooting and tracing
// (backend/lighting/photonshootingtask.cpp ShootPhotonsAtObject, photons.cpp PhotonTrace and
// LightTargetCombo) and the photons' share of a surface's light (trace.cpp
// ComputePhotonDiffuseLight). These are members of the Whitted integrator (whitted.h): the
// photons go through the same textures, reflectivity and interiors as its rays.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>

#include "core/error.h"
#include "core/float.h"
#include "render/integrators/whitted.h"
#include "render/materials/classic_finish.h"
#include "render/prepare/containing.h"
#include "render/prepare/geometry.h"
#include "render/textures/pattern.h"
#include "scene/features.h"

namespace glint::render {
namespace {

// splitmix64 seeded per light and target: the shooting's jitter, the same every render.
double draw(uint64_t* state) {
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) / 9007199254740992.0;
}

double greyscale(const Color& c) { return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b; }

// The most photons a scene may store (surface and media together): about 0.7 GB.
constexpr size_t kMaxPhotons = 10'000'000;

// Rotation of `v` about unit `axis` by `angle` (Rodrigues).
Vec3 rotate_about(const Vec3& v, const Vec3& axis, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1 - c));
}

// A flag merged from the light's and the target's photons blocks: on in one, off in neither.
bool merged_on(int light, int object) {
    return (light == 1 || object == 1) && light != 0 && object != 0;
}

[[noreturn]] void too_many_photons(const FileLoc& at) {
    throw Error(ErrorKind::Render, at,
                "photons: the spacing would shoot more than " + std::to_string(10 * kMaxPhotons) +
                    " or store more than " + std::to_string(kMaxPhotons) +
                    " photons; raise spacing (or lower count)");
}

// LightTargetCombo::computeAnglesAndDeltas: how photons from `light` are aimed at a target's
// bounding sphere, `separation` apart at the target.
struct Aim {
    Vec3 to_centre, left, light_dir;
    double dist = 0, spread = 0, dtheta = 0, max_theta = 0;
    bool area = false;
    int ax = 1, ay = 1;  // area_light grid of shooting positions
    bool parallel = false;
    // About how many photons the rings shoot: the cone's solid angle (a parallel beam's disc)
    // over each photon's.
    double shots() const {
        if (!(dtheta > 0)) return 0;
        const double cover = parallel ? kPi * max_theta * max_theta
                                      : 2 * kPi * (1 - std::cos(std::min(max_theta, kPi)));
        return cover / (dtheta * dtheta) * ax * ay;
    }
};

Aim aim_at(const scene::Light& light, const Vec3& centre, double radius, double separation) {
    Aim a;
    a.parallel = light.parallel;
    const Vec3 v = centre - light.location;
    a.dist = length(v);
    a.to_centre = a.dist > 0 ? v / a.dist : Vec3(0, 0, 1);
    a.light_dir = normalize(light.point_at - light.location);
    const Vec3 up = std::fabs(std::fabs(a.to_centre.z) - 1) < 0.1 ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
    a.left = normalize(cross(light.parallel ? a.light_dir : a.to_centre, up));
    a.spread = separation;
    if (!light.parallel) a.spread /= a.dist;
    a.area = light.area && light.photon_area_light && !light.parallel;
    if (a.area) {
        a.ax = light.area->size1;
        a.ay = light.area->size2;
        a.spread *= std::sqrt(static_cast<double>(a.ax * a.ay));
    }
    if (!(a.spread > 0)) return a;
    a.dtheta = light.parallel ? a.spread : std::atan(a.spread);
    if (light.parallel) {
        a.max_theta = radius;
    } else if (a.dist >= radius) {
        a.max_theta = std::asin(radius / a.dist);
    } else {
        a.max_theta = kPi;
        if (std::fabs(a.dist) < kPovEpsilon) {
            a.left = Vec3(0, 1, 0);
            a.to_centre = Vec3(0, 0, 1);
        }
        a.dist = radius;
    }
    return a;
}

}  // namespace

// One photon's travel (POV-Ray's per-thread photon state).
struct Whitted::PhotonPath {
    const scene::Light* light = nullptr;
    int target = -1;
    double spread = 0;  // photon separation at one unit from the light (parallel: absolute)
    double depth = 0;   // length travelled from the light
    bool pass_prev = true, pass_this = false;
    bool hit_target = false;
    int max_level = 5;
    double adc = 1.0 / 255;
    std::vector<Photon>* out = nullptr;
    std::vector<Photon>* media_out = nullptr;  // media photons
    uint64_t random = 0;                         // the shooting's random state
};

void Whitted::shoot_photons(int threads) {
    const scene::Photons& settings = *scene_.global.photons;
    if (!settings.load_file.empty()) {
        // The photons of an earlier render, instead of shooting (photons { load_file }).
        std::vector<Photon> all, media;
        read_photon_file(settings.load_file, &all, &media, settings.loc);
        keep_photons(std::move(all), std::move(media));
        return;
    }
    // The targets and their bounding spheres (ShootingDirection::compute).
    struct Target {
        int object;
        Vec3 centre;
        double radius;
    };
    std::vector<Target> targets;
    Diagnostics quiet;
    for (size_t i = 0; i < scene_.objects.size(); ++i) {
        if (!(scene_.objects[i].photon_target > 0)) continue;
        scene::Scene one;
        one.objects.push_back(scene_.objects[i]);
        one.meshes = scene_.meshes;
        one.materials = scene_.materials;
        one.functions = scene_.functions;  // an isosurface needs its function to be built
        const Bounds3 box = build_geometry(one, scene::analyze(one), quiet)->bounds();
        if (box.empty() || !std::isfinite(box.lo.x + box.lo.y + box.lo.z + box.hi.x + box.hi.y + box.hi.z))
            continue;
        targets.push_back({static_cast<int>(i), (box.lo + box.hi) * 0.5, length(box.hi - box.lo) * 0.5});
    }
    struct Combo {
        const scene::Light* light;
        const Target* target;
    };
    std::vector<Combo> combos;
    for (const scene::Light& l : scene_.lights) {
        if (l.blender || l.shadowless) continue;  // fill lights shoot no photons
        for (const Target& t : targets) {
            const scene::Object& o = scene_.objects[static_cast<size_t>(t.object)];
            if (merged_on(l.photon_refraction, o.photon_refraction) ||
                merged_on(l.photon_reflection, o.photon_reflection))
                combos.push_back({&l, &t});
        }
    }
    double separation = settings.spacing;
    if (settings.count > 0 && !combos.empty()) {
        // PhotonEstimationTask: guess the photons the spacing would give, then scale it.
        double estimate = 0;
        for (const Combo& c : combos) {
            const scene::Object& o = scene_.objects[static_cast<size_t>(c.target->object)];
            const bool rfr = merged_on(c.light->photon_refraction, o.photon_refraction);
            const bool rfl = merged_on(c.light->photon_reflection, o.photon_reflection);
            double x = c.target->radius / (o.photon_target * settings.spacing);
            x = x * x * kPi;
            if (rfr && rfl) x *= 1.5;
            if (o.photon_collect && rfr) x *= rfl ? 3 : 2;
            estimate += x * 0.5;
        }
        separation *= std::sqrt(estimate / settings.count);
    }
    // A spacing too fine for the scene would shoot for hours: estimate first.
    double shots = 0;
    for (const Combo& c : combos) {
        const scene::Object& o = scene_.objects[static_cast<size_t>(c.target->object)];
        shots += aim_at(*c.light, c.target->centre, c.target->radius, o.photon_target * separation)
                     .shots();
    }
    if (shots > 10.0 * kMaxPhotons) too_many_photons(settings.loc);
    std::vector<std::vector<Photon>> found(combos.size()), found_media(combos.size());
    // A spacing too fine for the scene would store photons until memory runs out: stop at
    // kMaxPhotons with an error instead.
    std::atomic<size_t> stored{0}, shot{0};
    std::atomic<bool> too_many{false};
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    arena.execute([&] {
        tbb::parallel_for(size_t(0), combos.size(), [&](size_t k) {
            const Combo& c = combos[k];
            const scene::Light& light = *c.light;
            const Target& t = *c.target;
            const scene::Object& o = scene_.objects[static_cast<size_t>(t.object)];
            PhotonPath path;
            path.light = &light;
            path.target = t.object;
            path.max_level = settings.max_trace_level >= 0 ? settings.max_trace_level
                                                           : max_level_;
            path.adc = settings.adc_bailout >= 0 ? settings.adc_bailout : adc_bailout_;
            path.out = &found[k];
            path.media_out = &found_media[k];
            const Aim aim = aim_at(light, t.centre, t.radius, o.photon_target * separation);
            if (!(aim.spread > 0)) return;
            const Vec3& to_centre = aim.to_centre;
            const Vec3& left = aim.left;
            const Vec3& light_dir = aim.light_dir;
            const Vec3 to_centre_v = t.centre - light.location;
            const double dist = aim.dist, dtheta = aim.dtheta, max_theta = aim.max_theta;
            const bool parallel = light.parallel;
            const bool area = aim.area;
            const int ax = aim.ax, ay = aim.ay;
            path.spread = aim.spread;
            path.random = 0x9E3779B97F4A7C15ull * (k + 1);
            auto random = [&path] { return draw(&path.random); };
            const PreparedLight beam(light);
            bool hit_once = false;
            Interiors inside;
            Vec3 inside_at;
            bool have_inside = false;
            for (double theta = 0; theta < max_theta && !too_many; theta += dtheta) {
                path.hit_target = false;
                const double dphi = theta < kPovEpsilon ? 2 * kPi
                                    : parallel          ? dtheta / theta
                                                        : dtheta / std::sin(theta);
                const double min_phi = -kPi + dphi * random() * 0.5;
                const double max_phi = kPi - dphi / 2 + (min_phi + kPi);
                for (double phi = min_phi; phi < max_phi && !too_many; phi += dphi) {
                    const double jphi = phi + dphi * (random() - 0.5) * settings.jitter;
                    const double jtheta = theta + dtheta * (random() - 0.5) * settings.jitter;
                    for (int i = 0; i < ax; ++i) {
                        for (int j = 0; j < ay; ++j) {
                            Ray ray;
                            ray.origin = light.location;
                            if (parallel) {
                                ray.dir = light_dir;
                                // From the plane through the target's centre across the
                                // beam, "theta" being the radius.
                                const Vec3 base = t.centre - light_dir * dot(light_dir, to_centre_v);
                                ray.origin = base - light_dir * dist +
                                             rotate_about(left * jtheta, light_dir, jphi);
                            } else {
                                const Vec3 v = -left * std::sin(jtheta) + to_centre * std::cos(jtheta);
                                ray.dir = rotate_about(v, to_centre, jphi);
                                if (area) {
                                    // recomputeForAreaLight: from the grid's cell centre.
                                    const scene::AreaLight& a = *light.area;
                                    const double fu = ax > 1 ? (i - (ax - 1) / 2.0) / (ax - 1) : 0;
                                    const double fv = ay > 1 ? (j - (ay - 1) / 2.0) / (ay - 1) : 0;
                                    ray.origin = light.location + a.axis1 * fu + a.axis2 * fv;
                                }
                            }
                            // Spot and cylinder light: the beam's falloff.
                            const double attenuation = beam.beam(ray.origin, ray.dir) / (ax * ay);
                            if (attenuation < 0.00001) continue;
                            path.depth = 0;
                            path.pass_prev = true;
                            path.pass_this = false;
                            // The objects around the photon's start: found once per start
                            // point (a point light's photons all share one).
                            if (!have_inside || !(ray.origin == inside_at)) {
                                inside = Interiors();
                                for (const Containing& ci :
                                     objects_containing(scene_, geometry_, ray.origin, ray.dir))
                                    inside.append(
                                        ci.object, interior_id(ci.material),
                                        scene_.materials[static_cast<size_t>(ci.material)]
                                            .interior.ior,
                                        ci.material, ci.hollow);
                                inside_at = ray.origin;
                                have_inside = true;
                            }
                            const size_t before = found[k].size() + found_media[k].size();
                            photon_trace(ray, light.color * attenuation, 1.0, 0, inside, false,
                                         path);
                            const size_t added =
                                found[k].size() + found_media[k].size() - before;
                            // Shots that store nothing count a tenth: a spacing that misses
                            // everything must end too.
                            if (stored.fetch_add(added) + added > kMaxPhotons ||
                                shot.fetch_add(1) + 1 > 10 * kMaxPhotons)
                                too_many = true;
                        }
                    }
                }
                if (path.hit_target) hit_once = true;
                // autostop: once the target was hit, a ring that misses it ends the shooting.
                if (hit_once && !path.hit_target && theta > settings.autostop * max_theta) break;
            }
        });
    });
    if (too_many) too_many_photons(settings.loc);
    std::vector<Photon> all, media;
    for (auto& f : found) all.insert(all.end(), f.begin(), f.end());
    for (auto& f : found_media) media.insert(media.end(), f.begin(), f.end());
    if (!settings.save_file.empty()) write_photon_file(settings.save_file, all, media, settings.loc);
    keep_photons(std::move(all), std::move(media));
}

void Whitted::keep_photons(std::vector<Photon> surface, std::vector<Photon> media) {
    const scene::Photons& settings = *scene_.global.photons;
    photons_ = std::make_unique<PhotonMap>(std::move(surface), settings);
    if (!media.empty()) {
        media_photons_ = std::make_unique<PhotonMap>(std::move(media), settings, true);
        media_.set_photons(media_photons_.get());
    }
}

void Whitted::photon_media(const Ray& ray, double seg, Color* light, int level,
                           const Interiors& in, PhotonPath& path) const {
    // The media of the hollow objects the photon crosses (not the atmosphere's): they dim
    // it, and with `media` photons on they keep photons along the way
    // (PhotonMediaFunction::DepositMediaPhotons, one interval).
    if (!features_.media || in.count == 0 || !hollow(in)) return;
    std::vector<const scene::Media*> media;
    interior_media(in, &media);
    if (media.empty()) return;
    const scene::Photons& settings = *scene_.global.photons;
    const Vec3 dir = ray.dir / length(ray.dir);
    bool extinction = false, scattering = false, collects = false;
    for (const scene::Media* m : media) {
        extinction = extinction || !m->absorption.is_black() || !m->scattering.is_black();
        scattering = scattering || !m->scattering.is_black();
        collects = collects || m->collect;
    }
    const scene::Light& l = *path.light;
    if (level > 1 && !path.pass_prev && settings.media_steps > 0 && extinction && scattering &&
        collects) {
        const double step = path.spread * (l.parallel ? 1.0 : path.depth);
        int n = step > 0 ? static_cast<int>(seg / (step * settings.media_factor)) : 0;
        double factor = settings.media_factor;
        if (n > settings.media_steps) {
            n = settings.media_steps;
            factor = seg / (step * n);
        }
        for (int j = 0; j < n; ++j) {
            const double d =
                (j + 0.5 + (draw(&path.random) - 0.5) * settings.jitter) / n * seg;
            const double travelled = path.depth + d;
            // addMediaPhoton over the colour the photon had entering the medium.
            double fade = 1;
            if (l.fade_power > 0 && std::fabs(l.fade_distance) > kPovEpsilon)
                fade = 2.0 / (1.0 + std::pow(travelled / l.fade_distance, l.fade_power));
            Color power = *light * (factor * path.spread * (l.parallel ? 1.0 : travelled));
            power *= fade * path.spread * path.spread;
            if (!l.parallel) power *= travelled * travelled;
            path.media_out->push_back({ray.origin + dir * d, -dir, power});
        }
    }
    auto no_light = [](size_t, const Vec3&, Color*, Vec3*) { return false; };
    media_.compute(media, ray.origin, dir, seg, true, no_light, light, nullptr);
}

bool Whitted::photon_refracts(const scene::Light& light, int object) const {
    const scene::Object& o = scene_.objects[static_cast<size_t>(object)];
    return o.photon_target > 0 && merged_on(light.photon_refraction, o.photon_refraction);
}

void Whitted::photon_trace(const Ray& ray, const Color& light, double weight, int level,
                           const Interiors& in, bool continued, PhotonPath& path) const {
    // PhotonTrace::TraceRay.
    // Every surface counts a level here, even where the ray goes on unbent (POV-Ray's
    // PhotonTrace ignores continuedRay): the first surface must be the target.
    (void)continued;
    if (level >= path.max_level || weight < path.adc) return;
    ++level;
    Hit hit;
    RayState state;
    state.primary = level == 1;
    if (!find_hit(ray, state, &hit)) return;
    const bool old_prev = path.pass_prev;
    path.pass_prev = path.pass_this;
    auto restore = [&] {
        path.pass_this = path.pass_prev;
        path.pass_prev = old_prev;
    };
    const scene::Object& obj = scene_.objects[static_cast<size_t>(hit.object)];
    path.pass_this = false;
    if (level == 1 || path.pass_prev) {
        // The first surface must be the target (or something photons pass through).
        if (hit.object == path.target && obj.photon_target > 0) {
            path.hit_target = true;
        } else if (obj.photon_pass_through) {
            path.pass_this = true;
        } else {
            restore();
            return;
        }
    }
    photon_surface(ray, hit, light, weight, level, in, path);
    restore();
}

void Whitted::photon_surface(const Ray& ray, const Hit& hit, Color light, double weight,
                             int level, const Interiors& in, PhotonPath& path) const {
    // PhotonTrace::ComputeLightedTexture.
    const scene::Material& mat = scene_.materials[static_cast<size_t>(hit.material)];
    const scene::Object& obj = scene_.objects[static_cast<size_t>(hit.object)];
    const double len = length(ray.dir);
    photon_media(ray, hit.t * len, &light, level, in, path);
    light *= mat.interior.old_refraction;
    if (in.contains(hit.object, interior_id(hit.material)) &&
        std::fabs(mat.interior.fade_distance) > kPovEpsilon &&
        mat.interior.fade_power > 0)
        light *= fade(mat.interior, hit.t * len);
    path.depth += hit.t * len;
    if (level > 1 && !path.pass_prev && obj.photon_collect) {
        // addSurfacePhoton: POV-Ray's light fading undone, spread over the path's length.
        const scene::Light& l = *path.light;
        double att = 1;
        if (l.fade_power > 0 && std::fabs(l.fade_distance) > kPovEpsilon)
            att = 2.0 / (1.0 + std::pow(path.depth / l.fade_distance, l.fade_power));
        Color power = light * (att * path.spread * path.spread);
        if (!l.parallel) power *= path.depth * path.depth;
        path.out->push_back({hit.p, normalize(-ray.dir), power});
    }
    Vec3 n = hit.n;
    if (dot(n, ray.dir) > 0) n = -n;
    if (path.pass_this) {
        // Straight through an object photons pass.
        Interiors next = in;
        const int id = interior_id(hit.material);
        if (!next.remove(hit.object, id))
            next.append(hit.object, id, mat.interior.ior, hit.material,
                        (hit.flags & kHollow) != 0);
        Ray r;
        r.dir = ray.dir;
        r.origin = offset_ray_origin(hit.p, hit.p_error, hit.ng, ray.dir);
        photon_trace(r, light, weight, level, next, true, path);
        path.depth -= hit.t * len;
        return;
    }
    // The texture the photon meets: patterned textures pick the nearer entry of their map.
    const scene::Texture* tex = &mat.texture;
    Vec3 at_p = texture_point({hit.p, hit.uv, hit.has_uv}, mat.uv_points).p;
    for (int guard = 0; guard < 16 && tex->kind != scene::PatternKind::Plain; ++guard) {
        const Vec3 local =
            tex->transform.is_identity() ? at_p : tex->transform.inverse_point(at_p);
        const Vec3 tp = tex->params.warps.empty() ? local : warp_point(tex->kind, tex->params, local);
        if (tex->kind == scene::PatternKind::Average) {
            if (tex->texture_map.empty()) return;
            tex = &tex->texture_map[0].texture[0];
        } else {
            const double value = evaluate_pattern(tex->kind, tex->params, local, pigments_.context());
            if (is_block_pattern(tex->kind)) {
                tex = &tex->entries[block_index(value, tex->entries.size())];
            } else {
                if (tex->texture_map.empty()) return;
                const BlendPick b = search_blend_map(tex->texture_map, value);
                tex = &tex->texture_map[b.fraction >= 0.5 ? b.cur : b.prev].texture[0];
            }
        }
        at_p = tp;
    }
    const PatternPoint at{at_p, hit.uv, hit.has_uv};
    const int layer_count = 1 + static_cast<int>(tex->layers.size());
    LayerReflection refl[kMaxLayers];
    int used = 0;
    Color fil_col(1.0);
    double trans = 1.0;
    Vec3 top_normal = n;
    const TextureStack no_stack{};
    for (int li = 0; li < layer_count && trans > path.adc && used < kMaxLayers; ++li) {
        const scene::Texture& layer = li == layer_count - 1 ? *tex : tex->layers[layer_count - 2 - li];
        const ClassicFinish& f = materials_.classic_finish(layer.finish, hit.material);
        const Vec3 lay_n = layer_normal(layer.normal, at, n, no_stack);
        if (li == 0) top_normal = lay_n;
        scene::ColorFT pig;
        const bool found = pigments_.evaluate(layer.pigment, at, &pig);
        double refl_weight = weight * trans;
        const double cos_incidence = -dot(normalize(ray.dir), lay_n);
        RayState rs;
        rs.interiors = in;
        Color reflec = f.reflects() ? reflectivity(f, cos_incidence,
                                                   relative_ior(rs, hit.object, interior_id(hit.material), mat.interior.ior),
                                                   &refl_weight)
                                    : Color();
        if (f.reflect_metallic != 0.0)
            reflec = metallic_tint(f.reflect_metallic, cos_incidence, pig.rgb * fil_col, reflec);
        refl[used++] = {refl_weight, lay_n, reflec, f.reflect_exponent, &f};  // no irid on photons
        if (found) {
            fil_col *= Color(pig.rgb.r * pig.filter + pig.transmit,
                             pig.rgb.g * pig.filter + pig.transmit,
                             pig.rgb.b * pig.filter + pig.transmit);
            if (f.conserve_energy)
                fil_col *= Color(std::min(1.0, 1.0 - reflec.r), std::min(1.0, 1.0 - reflec.g),
                                 std::min(1.0, 1.0 - reflec.b));
        }
        trans = std::min(1.0, std::fabs(greyscale(fil_col)));
    }
    const scene::Light& l = *path.light;
    bool tir = false;
    if (merged_on(l.photon_refraction, obj.photon_refraction) && trans > path.adc &&
        features_.secondary_rays()) {
        // ComputeRefractionForPhotons: the light through the layers' filter.
        const double w = weight * std::max({fil_col.r, fil_col.g, fil_col.b, 0.0});
        Interiors next = in;
        const double ior = cross_interface(hit, &next);
        Ray r;
        const Vec3 d = normalize(ray.dir);
        if (std::fabs(ior - 1.0) < kPovEpsilon) {
            r.dir = d;
            r.origin = offset_ray_origin(hit.p, hit.p_error, hit.ng, r.dir);
            photon_trace(r, light * fil_col, w, level, next, true, path);
        } else if (refracted_direction(d, top_normal, ior, &r.dir)) {
            r.origin = offset_ray_origin(hit.p, hit.p_error, hit.ng, r.dir);
            photon_trace(r, light * fil_col, w, level, next, false, path);
        } else {
            tir = true;  // the whole light reflects
            Ray m;
            m.dir = reflected_direction(d, top_normal, n);
            m.origin = offset_ray_origin(hit.p, hit.p_error, hit.ng, m.dir);
            photon_trace(m, light, w, level, in, false, path);
        }
    }
    if (merged_on(l.photon_reflection, obj.photon_reflection)) {
        for (int i = 0; i < used; ++i) {
            const LayerReflection& r = refl[i];
            if (tir && std::fabs(top_normal.x - r.normal.x) <= kPovEpsilon &&
                std::fabs(top_normal.y - r.normal.y) <= kPovEpsilon &&
                std::fabs(top_normal.z - r.normal.z) <= kPovEpsilon)
                continue;
            if (r.reflec.is_black()) continue;
            Color c = light;
            if (r.exponent != 1.0)
                c = Color(std::pow(c.r, r.exponent), std::pow(c.g, r.exponent),
                          std::pow(c.b, r.exponent));
            c *= r.reflec;
            Ray m;
            m.dir = reflected_direction(normalize(ray.dir), r.normal, n);
            m.origin = offset_ray_origin(hit.p, hit.p_error, hit.ng, m.dir);
            photon_trace(m, c, r.weight * r.reflec.max(), level, in, false, path);
        }
    }
    path.depth -= hit.t * len;
}

Color Whitted::photon_light(const ClassicFinish& f, const Hit& hit, const Ray& ray,
                            const Vec3& lay_n, const Vec3& raw_n, const Color& pigment,
                            double att, bool highlights, PhotonGather* gathered) const {
    // ComputePhotonDiffuseLight: each photon lights the point like a light from where it came
    // (the Lambert cosine undone, at most tenfold), over the disc it was gathered from.
    if (f.diffuse == 0.0 && f.diffuse_back == 0.0 && f.specular == 0.0 && f.phong == 0.0)
        return Color();
    if (gathered->radius == 0 && gathered->photons.empty())
        photons_->gather(hit.p, &lay_n, gathered);
    if (!(gathered->radius > 0)) return Color();
    const bool double_illuminate = (hit.flags & kDoubleIlluminate) != 0;
    Color sum;
    for (const Photon* ph : gathered->photons) {
        const Vec3& dir = ph->to_source;
        const double c = std::clamp(dot(raw_n, dir), 0.1, 1.0);
        const Color lc = ph->power / c;
        const bool backside = !double_illuminate && dot(lay_n, dir) < kPovEpsilon;
        if (backside && f.diffuse_back == 0.0) continue;
        sum += diffuse_term(f, lay_n, dir, pigment, lc, att, backside);
        if (!highlights || backside) continue;
        if (f.phong > 0.0) sum += phong_term(f, lay_n, dir, ray.dir, pigment, lc);
        if (f.specular > 0.0) sum += specular_term(f, lay_n, dir, ray.dir, pigment, lc);
    }
    return sum / (kPi * gathered->radius * gathered->radius);
}

}  // namespace glint::render
