#include "render/integrators/path.h"

#include <algorithm>
#include <cmath>

#include <tbb/task_arena.h>

#include "core/float.h"
#include "render/bsdf/bsdf.h"
#include "render/bsdf/graph_closures.h"
#include "render/bsdf/shading_normal.h"
#include "render/lights/sky.h"
#include "render/media/subsurface.h"

namespace glint::render {
namespace {

// Sampler pairs used per bounce: (unused, roulette), BSDF lobe and direction, (unused, light
// pick), then one per light slot. Alpha coins come from pairs after all the bounces' ones, one
// per test, so a see-through surface does not shift the random numbers of the bounces after it.
constexpr uint32_t kPairsPerVertex = 3 + PathLights::kSampleAllMax;
// Stochastic-alpha pass-throughs allowed on top of max_depth bounces.
constexpr int kMaxAlphaSkips = 64;
// Media draw as many random numbers as their collisions need, from pairs after the alpha
// coins' (at most one per pass-through).
constexpr uint32_t kAlphaPairs = 4096;

double power_heuristic(double a, double b) {
    const double a2 = a * a, b2 = b * b;
    if (!(a2 + b2 > 0)) return 0;
    if (std::isinf(a2)) return 1;
    return a2 / (a2 + b2);
}

bool finite(const Color& c) {
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}

double average(const Color& c) { return (c.r + c.g + c.b) / 3; }

// The chance that a ray passes straight through a surface whose closures are `cl`: the
// transparency's share against the BSDFs' sample weights, as Cycles picks among closures
// (0 when nothing is transparent).
double transparent_share(const shader::ClosureList& cl) {
    const double tw = average(cl.transparent);
    if (!(tw > 0)) return 0;
    double sw = 0;
    for (int i = 0; i < cl.count(); ++i) sw += cl.items[i].sample_weight;
    return sw > 0 ? tw / (tw + sw) : 1.0;
}

}  // namespace


PathIntegrator::PathIntegrator(const PreparedScene& prepared, const PathSettings& settings)
    : scene_(prepared.scene),
      geometry_(*prepared.geometry),
      materials_(prepared.materials),
      graphs_(prepared.graphs.get()),
      pigments_(prepared.textures.get(),
                PatternContext{scene_.global.noise_generator, 10, &scene_.functions,
                               prepared.pattern_objects.get()}),
      settings_(settings),
      rays_(64) {
    int world = 0;
    if (graphs_ && graphs_->world()) {
        world = graphs_->world()->constant() ? 1 : 2;
        if (world == 1) world_constant_ = environment(Vec3(0, 0, 1));
    }
    lights_.emplace(scene_, materials_.emission(),
                    [this](const Vec3& d) { return environment(d); }, prepared.textures.get(),
                    world, settings.light_tree);
    setup_media();
}


void PathIntegrator::graph_closures(const PathMaterial& row, const Hit& hit, const Vec3& dir,
                                    const shader::RayState& state,
                                    shader::ClosureList* out) const {
    if (row.constant_closures) {
        *out = *row.constant_closures;
        return;
    }
    if (row.normal_closures) {
        // What the program gives with GraphShading::normal() as its N, bit for bit.
        *out = *row.normal_closures;
        const Vec3 n = shader::GraphShading::normal(hit, dir).to_vec3();
        out->N = n;
        for (shader::Closure& c : out->items) {
            if (c.n_from_globals) c.N = n;
            if (c.clearcoat_n_from_globals) c.clearcoat_N = n;
        }
        return;
    }
    row.program->evaluate(graphs_->globals(hit, dir, state), out);
}

Vec3 PathIntegrator::subsurface_exit_normal(const PathMaterial* row, const Hit& hit,
                                            const Vec3& dir, double travelled) const {
    // Cycles' surface_shader_bssrdf_normal: the BSSRDFs' normals there, by their weights.
    if (!row || !row->program || row->constant_closures) return hit.n;
    shader::RayState state;
    state.camera = false;
    state.travelled = travelled;  // bump's footprint: the entry's (Cycles keeps its dP)
    shader::ClosureList cl;
    graph_closures(*row, hit, dir, state, &cl);
    Vec3 sum;
    for (int i = 0; i < cl.count(); ++i) {
        const shader::Closure& c = cl.items[i];
        const bool bssrdf = c.kind == shader::ClosureKind::Subsurface ||
                            (c.kind == shader::ClosureKind::Principled && c.subsurface > 1e-5);
        if (bssrdf && length_squared(c.N) > 0)
            sum += normalize(c.N) * std::fabs((c.weight.r + c.weight.g + c.weight.b) / 3);
    }
    if (!(length_squared(sum) > 0)) return hit.n;
    const Vec3 n = normalize(sum);
    return dot(hit.ng, dir) > 0 ? -n : n;  // the closures face the viewer; the set the outside
}

Color PathIntegrator::environment(const Vec3& dir, const shader::RayState& state) const {
    if (world_constant_) return *world_constant_;
    if (graphs_ && graphs_->world()) {
        shader::ClosureList cl;
        graphs_->world()->evaluate(graphs_->world_globals(dir, state), &cl);
        return cl.emission;
    }
    return environment(dir);
}

void PathIntegrator::add_pov_subsurface(const SurfacePbr& s, const Hit& hit, const Vec3& dir,
                                        bool diffuse_ancestor, ClosureSet* set) const {
    // POV-Ray's subsurface in place of the diffuse lobe: a random walk of the base colour
    // (as Cycles' Random Walk), plain diffuse after a diffuse bounce.
    const PrincipledParams& p = s.bsdf;
    const Color weight = p.base * ((1 - p.metallic) * (1 - p.transmission));
    if (!(std::fabs(average(weight)) >= 1e-5)) return;
    const Vec3 n = dot(hit.n, dir) > 0 ? -hit.n : hit.n;
    if (diffuse_ancestor) {
        set->add(Bsdf::lambert(Color(1, 1, 1)), weight, n, std::fabs(average(weight)));
        return;
    }
    Bssrdf b;
    b.weight = weight;
    b.radius = s.subsurface_radius;
    b.albedo = p.base;
    b.n = n;
    Color diffuse;
    b.setup(false, std::clamp(p.ior, 1.01, 3.8), &diffuse);
    if (!diffuse.is_black())
        set->add(Bsdf::lambert(Color(1, 1, 1)), diffuse, n, std::fabs(average(diffuse)));
    set->add(b);
}

SurfacePbr PathIntegrator::surface(Hit& hit, const Vec3& dir) const {
    const PathMaterial* row = materials_.path(hit.material);
    if (!row) {
        SurfacePbr s;
        s.bsdf.specular = 0;
        return s;
    }
    if (row->constant) return *row->constant;
    const scene::Material& m = scene_.materials[hit.material];
    // The slope pattern reads the surface's own (outward) normal here: the path tracer shades
    // without the ray's side, which only differs from POV-Ray's facing normal seen from inside.
    const PatternPoint at = texture_point({hit.p, hit.uv, hit.has_uv, &hit.n, &dir}, m.uv_points);
    if (!m.pbr.derived) {
        // Only materials with maps get here. A surface without uvs reads its maps at uv
        // (0, 0), as Cycles reads an Image Texture on a mesh without a UV map (a missing
        // image's magenta shows there too); its normal stays, having no tangents to bump.
        const PbrMaps& maps = materials_.maps(*row);
        if (!hit.has_uv) return pbr_surface(m.pbr, maps, Vec2(0, 0));
        if (maps.bump) hit.n = mapped_normal(maps, hit.uv, hit.n, hit.dpdu, hit.dpdv);
        return pbr_surface(m.pbr, maps, hit.uv);
    }
    const scene::Texture& t = base_texture(m.texture);
    scene::ColorFT c;
    if (!pigments_.evaluate(t.pigment, at, &c)) c = scene::ColorFT(Color(1, 1, 1), 0, 1);
    return pov_to_pbr(t.finish, m.interior, c, sslt_mm_);
}

Color PathIntegrator::environment(const Vec3& dir) const {
    if (graphs_ && graphs_->world()) {
        // As Cycles evaluates the world for light sampling and its importance map
        // (PATH_RAY_EMISSION): no ray-type flag is set.
        shader::RayState state;
        state.camera = false;
        return environment(dir, state);
    }
    return sky_radiance(scene_, pigments_, dir);
}

Color PathIntegrator::transmittance(const Vec3& origin, const Vec3& dir, double dist,
                                    double time, MediumStack stack, uint32_t seed,
                                    uint64_t* rays) const {
    // Stop short of the light sample so an emitter does not shadow itself.
    const double tmax = std::isinf(dist) ? kInfinity : dist * (1 - 1e-5);
    Ray r;
    r.origin = origin;
    r.dir = dir;
    r.tmax = tmax;
    r.time = time;
    ++*rays;
    if (!materials_.any_alpha() && !has_media_)
        return geometry_.occluded(r) ? Color() : Color(1, 1, 1);
    Color t(1, 1, 1);
    double travelled = 0;
    ActiveMedium act[MediumStack::kMax + 1];
    // The media's transmittance from the current origin over `len`.
    auto through_media = [&](double len) {
        if (!has_media_) return;
        double step;
        const int na = active_media(stack, act, &step);
        if (na > 0) t *= media_transmittance(act, na, step, r.origin, dir, len, &seed);
    };
    for (int i = 0; i < kMaxAlphaSkips; ++i) {
        Hit h;
        if (i > 0) ++*rays;
        if (!geometry_.intersect(r, &h)) {
            through_media(r.tmax);
            return t;
        }
        through_media(h.t);
        if (t.is_black()) return Color();
        if (!(h.flags & kNoShadow)) {
            const PathMaterial* pm = materials_.path(h.material);
            if (!pm || !pm->has_alpha) return Color();
            if (pm->program) {
                // A node graph lets through its transparent closures' weight.
                shader::RayState state;
                state.camera = false;
                state.shadow = true;
                shader::ClosureList cl;
                graph_closures(*pm, h, dir, state, &cl);
                t *= cl.transparent;
                if (t.is_black()) return Color();
                if (has_media_) stack.cross(h, dir, *this);
                const Vec3 o = offset_ray_origin(h.p, h.p_error, h.ng, dir);
                travelled += length(o - r.origin);
                r.origin = o;
                r.tmax = std::isinf(tmax) ? kInfinity : tmax - travelled;
                if (!(r.tmax > 0)) return t;
                continue;
            }
            // What passes: the uncovered fraction, and through an index-matched (IOR 1)
            // transmissive surface the transmitted part, tinted; refraction at any other IOR
            // bends the light, which only BSDF sampling can follow.
            const SurfacePbr s = surface(h, dir);
            Color pass(1 - s.alpha);
            if (s.bsdf.ior == 1.0 && s.bsdf.transmission > 0)
                pass += s.bsdf.base * (s.alpha * s.bsdf.transmission * (1 - s.bsdf.metallic));
            t *= pass;
            if (t.is_black()) return Color();
            if (has_media_) stack.cross(h, dir, *this);
        }
        const Vec3 o = offset_ray_origin(h.p, h.p_error, h.ng, dir);
        travelled += length(o - r.origin);
        r.origin = o;
        r.tmax = std::isinf(tmax) ? kInfinity : tmax - travelled;
        if (!(r.tmax > 0)) return t;
    }
    return Color();
}

bool PathIntegrator::photon_surface(Hit& hit, const Vec3& dir, double coin,
                                    PhotonSurface* out) const {
    out->set = ClosureSet(hit.ng, -dir);
    out->pass = false;
    const PathMaterial* row = materials_.path(hit.material);
    if (row && row->program) {
        shader::RayState state;
        state.camera = false;
        state.reflection = true;
        shader::ClosureList cl;
        graph_closures(*row, hit, dir, state, &cl);
        // Transparency by its share against the BSDFs', as li() picks it.
        double shade = 1;
        if (const double q = transparent_share(cl); q > 0) {
            if (coin < q) {
                out->pass = true;
                out->pass_weight = cl.transparent * (1 / q);
                return true;
            }
            shade = 1 / (1 - q);
        }
        const bool back = dot(hit.ng, dir) > 0;
        const Vec3 ns = length_squared(cl.N) > 0 ? normalize(cl.N) : hit.n;
        out->set.set_smooth_normal(back ? -ns : ns);
        for (int i = 0; i < cl.count(); ++i) {
            const shader::Closure& c = cl.items[i];
            Vec3 n = length_squared(c.N) > 0 ? normalize(c.N) : hit.n;
            if (back) n = -n;
            add_graph_closure(out->set, c, n, back ? -1.0 : 1.0, shade, false);
        }
        return out->set.count() > 0;
    }
    const SurfacePbr s = surface(hit, dir);
    if (s.alpha < 1 && coin >= s.alpha) {
        out->pass = true;
        out->pass_weight = Color(1, 1, 1);
        return true;
    }
    out->set.add(row && row->constant_bsdf ? *row->constant_bsdf : Bsdf::principled(s.bsdf),
                 Color(1, 1, 1), hit.n, 1);
    if (!s.subsurface_radius.is_black())
        add_pov_subsurface(s, hit, dir, false, &out->set);
    return true;
}

std::string PathIntegrator::photon_limits() const {
    if (has_media_) return "participating media (media, interiors with media, volumes)";
    if (sslt_mm_ > 0) return "POV-Ray's subsurface light transport";
    return {};
}

uint64_t PathIntegrator::rays() const {
    uint64_t sum = 0;
    for (const RayCount& c : rays_) sum += c.n.load(std::memory_order_relaxed);
    return sum;
}

Color PathIntegrator::li(const Ray& camera_ray, const PixelSampler& sampler, FirstHit* first,
                         VisiblePoint* vp) const {
    Color L;
    Color beta(1, 1, 1);
    Ray r = camera_ray;
    r.dir = normalize(r.dir);
    bool specular = true;  // camera rays and delta bounces: emission is not light-sampled
    double prev_pdf = 0;
    double seg_dist = 0;  // distance from the last scattering vertex (across alpha skips)
    Vec3 prev_p = r.origin;  // the last scattering vertex
    int depth = 0;
    uint64_t rays = 0;
    const PathLights& lights = *lights_;
    const int max_vertices = settings_.max_depth + 1 + kMaxAlphaSkips;
    if (first) *first = FirstHit{};
    const uint32_t alpha_base = 1 + static_cast<uint32_t>(max_vertices + 1) * kPairsPerVertex;
    uint32_t alpha_tests = 0;
    // Media: the objects the ray is in, and the random numbers their collisions draw.
    MediumStack stack;
    if (has_media_ && starts_at_camera(r)) stack = camera_stack_;
    // How far the segment may reach: a Blender camera's clip end, through transparent
    // surfaces too (Cycles keeps the camera ray's tmax across them); endless after a bounce.
    double seg_end = r.tmax;
    VolumeRandom volume_random{&sampler, alpha_base + kAlphaPairs};
    int volume_depth = 0;
    uint32_t scatterings = 0;  // BSDF samples so far (bounces and pass-throughs)
    int skips = 0;             // alpha holes and pass-throughs: they do not count as bounces
    double travelled = 0;      // path length from the camera to the last scattering vertex
    bool last_diffuse = false, last_reflected = true;  // the last bounce (Light Path node)
    // Bounces by kind (Cycles' counters); `last_hit`: a limit was reached, the next hit only
    // adds its emission.
    int diffuse_depth = 0, glossy_depth = 0, transmission_depth = 0;
    bool last_hit = false;
    // Cycles lets transparent_bounces + 1 pass-throughs by before it stops at a surface.
    const int max_skips = settings_.transparent_bounces >= 0
                              ? std::min(settings_.transparent_bounces + 1, kMaxAlphaSkips)
                              : kMaxAlphaSkips;
    double min_pdf = kInfinity;  // the lowest BSDF pdf on the path so far (Filter Glossy)
    // Whether the path is still the camera's own view, through nothing but transparent
    // surfaces (Cycles' PATH_RAY_TRANSPARENT_BACKGROUND): where such a path meets the world
    // under a transparent film, or a holdout, the pixel becomes transparent by its throughput.
    bool camera_view = true;
    auto hold_out = [&](const Color& weight) {
        if (first) first->transparent += average(beta * weight);
    };
    // A contribution to the pixel, clamped as Cycles clamps it: direct until the first bounce.
    auto add = [&](const Color& c) {
        const double limit = depth == 0 ? settings_.clamp_direct : settings_.clamp_indirect;
        const double sum = std::fabs(c.r) + std::fabs(c.g) + std::fabs(c.b);
        L += limit > 0 && sum > limit ? c * (limit / sum) : c;
    };
    // A subsurface walk's exit (Cycles' PATH_RAY_SUBSURFACE): the next vertex is where the
    // walk left the surface, shaded as diffuse there.
    bool at_exit = false, exit_fresnel = false;
    Hit exit_hit;
    bool diffuse_ancestor = false;  // a diffuse bounce so far (subsurface is diffuse after)
    // What a node graph's Light Path node reads of the ray that arrives at the next vertex (or
    // leaves the scene): Cycles' path flags and bounce counters.
    auto ray_state = [&] {
        shader::RayState state;
        state.camera = scatterings == 0;
        state.singular = specular && scatterings > 0;
        state.diffuse = last_diffuse;
        state.glossy = !last_diffuse && scatterings > 0;
        state.reflection = last_reflected && scatterings > 0;
        state.transmission = !last_reflected && scatterings > 0;
        state.length = seg_dist;
        state.travelled = travelled + seg_dist;
        state.depth = depth;
        state.diffuse_depth = diffuse_depth;
        state.glossy_depth = glossy_depth;
        state.transmission_depth = transmission_depth;
        state.transparent_depth = skips;
        return state;
    };
    for (int v = 0; v < max_vertices; ++v) {
        const uint32_t base = 1 + scatterings * kPairsPerVertex;
        Hit hit;
        bool found = true;
        if (at_exit) {
            hit = exit_hit;
        } else {
            ++rays;
            found = geometry_.intersect(r, &hit);
        }
        if (has_media_ && !at_exit) {
            ActiveMedium act[MediumStack::kMax + 1];
            double step = kInfinity;
            const int na = active_media(stack, act, &step);
            int event = 0;  // 0: through, 1: scattered, 2: absorbed
            double t = 0;
            MediumPoint mp;
            // (A ray that meets nothing goes on for ever through the media, clipped camera
            // rays too: Cycles' shade_volume sets FLT_MAX where no primitive was hit.)
            const double tmax = found ? hit.t : kInfinity;
            // Point lights' direct light in homogeneous media also comes by equiangular
            // sampling, MIS-weighted against the distance-sampled scattering below.
            bool equiangular = false;
            const Color beta0 = beta;
            if (na > 0 && settings_.volume_equiangular && std::isinf(step) &&
                lights.count() > 0 && depth < settings_.max_depth && !last_hit) {
                equiangular = true;
                for (int k = 0; k < na; ++k)
                    equiangular = equiangular && act[k].medium->homogeneous();
                if (equiangular)
                    add(equiangular_direct(act, na, r, tmax, beta0, stack, sampler, base,
                                           volume_random, &rays));
            }
            if (na > 0) {
                Color emitted;
                event = std::isinf(step)
                            ? track(act, na, r, tmax, volume_random, &beta, &emitted, &t, &mp)
                            : march(act, na, step, r, tmax, volume_random, &beta, &emitted,
                                    &t, &mp);
                add(emitted);
            }
            if (event == 2) break;
            if (event == 1) {
                const Vec3 sp = r.origin + r.dir * t;
                const Vec3 wo = -r.dir;
                if (first && !first->hit) {
                    first->hit = true;
                    const Color ss = mp.sigma_s(), st = mp.sigma_t();
                    first->albedo = Color(st.r > 0 ? ss.r / st.r : 0, st.g > 0 ? ss.g / st.g : 0,
                                          st.b > 0 ? ss.b / st.b : 0);
                    first->normal = wo;
                    first->depth = seg_dist + t;
                }
                if (depth >= settings_.max_depth || last_hit) break;
                // Next-event estimation from the scattering point, MIS against the phase.
                if (lights.count() > 0) {
                    const Sample2 ul = sampler.get2(base + 2);
                    auto light = [&](int slot, Sample2 u) {
                        PathLightSample ls;
                        if (!lights.sample(slot, sp, u, &ls)) return;
                        const double ph = phase_eval(mp, wo, ls.wi);
                        if (!(ph > 0)) return;
                        const uint32_t seed =
                            static_cast<uint32_t>(volume_random() * 4294967296.0);
                        const Color tr =
                            transmittance(sp, ls.wi, ls.dist, r.time, stack, seed, &rays);
                        if (tr.is_black()) return;
                        Color c = ls.value * tr * ph;
                        if (ls.environment) c *= environment(ls.wi);
                        if (ls.pdf > 0) c *= power_heuristic(ls.pdf, phase_pdf(mp, wo, ls.wi));
                        // MIS against equiangular sampling where it sampled this light:
                        // a point-like light seen from the segment's start (a spot light's
                        // cone may leave it out there).
                        PathLightSample at;
                        if (equiangular && ls.pdf == 0 && lights.sample(slot, r.origin, u, &at) &&
                            at.pdf == 0 && !std::isinf(at.dist))
                            c *= power_heuristic(distance_pdf(beta0, mp, t),
                                                 equiangular_pdf(r.origin, r.dir, tmax,
                                                                 r.origin + at.wi * at.dist, t));
                        add(beta * c);
                    };
                    if (lights.sample_all()) {
                        for (int k = 0; k < lights.count(); ++k)
                            light(k, sampler.get2(base + 3 + static_cast<uint32_t>(k)));
                    } else {
                        const int k = std::min(lights.count() - 1,
                                               static_cast<int>(ul.v * lights.count()));
                        light(k, sampler.get2(base + 3));
                    }
                }
                const Sample2 ud = sampler.get2(base + 1);
                Vec3 wi;
                double weight = 0, pdf = 0;
                if (!phase_sample(mp, wo, sampler.get2(base).u, ud.u, ud.v, &wi, &weight, &pdf))
                    break;
                ++scatterings;
                ++depth;
                // Volume bounces are their own kind (Cycles' Light Paths > Volume): past the
                // limit the path goes on only to add what it hits next.
                if (settings_.volume_bounces >= 0 && ++volume_depth > settings_.volume_bounces)
                    last_hit = true;
                beta *= weight;
                specular = false;
                last_diffuse = true;
                last_reflected = true;
                prev_pdf = pdf;
                camera_view = false;
                if (depth >= settings_.rr_start) {
                    const double q = std::min(1.0, std::sqrt(beta.max()));
                    if (!(sampler.get2(base).v < q)) break;
                    beta *= 1.0 / q;
                }
                if (beta.is_black() || !finite(beta)) break;
                r.origin = sp;
                r.dir = wi;
                r.tmax = seg_end = kInfinity;
                travelled += seg_dist + t;
                seg_dist = 0;
                prev_p = sp;
                continue;
            }
        }
        // Blender lights on the way (Cycles' lamps: rays pass through them).
        if (lights.has_visible_blender() && !at_exit)
            add(beta * lights.blender_emission(prev_p, r.dir, seg_dist,
                                               seg_dist + (found ? hit.t : r.tmax),
                                               specular ? -1.0 : prev_pdf, scatterings == 0));
        if (!found) {
            if (camera_view && settings_.film_transparent) {
                hold_out(Color(1, 1, 1));  // the world is not drawn, only its transparency
                break;
            }
            if (lights.has_environment()) {
                const double w =
                    specular ? 1.0 : power_heuristic(prev_pdf, lights.environment_pdf(r.dir));
                // The world sees the ray as it is (a Light Path node's Is Camera Ray shows one
                // background to the camera and lights with another).
                add(beta * environment(r.dir, ray_state()) * w);
            }
            break;
        }
        const PathMaterial* row = materials_.path(hit.material);
        const Sample2 ua = sampler.get2(base + 2);
        // The BSDFs here (several for a node graph), around the viewer's side.
        ClosureSet set(hit.ng, -r.dir);
        Color emission;
        Color albedo;
        if (at_exit) {
            at_exit = false;
            set.set_smooth_normal(hit.n);
            const Vec3 n = subsurface_exit_normal(row, hit, r.dir, travelled - hit.t);
            if (exit_fresnel) set.add(Lobe::subsurface_exit(), Color(1, 1, 1), n, 1);
            else set.add(Bsdf::lambert(Color(1, 1, 1)), Color(1, 1, 1), n, 1);
        } else if (row && row->program) {
            const shader::RayState state = ray_state();
            shader::ClosureList cl;
            graph_closures(*row, hit, r.dir, state, &cl);
            // Transparency (transparent closures, Principled alpha): straight through with the
            // probability of its share against the BSDFs', as Cycles picks among closures.
            double shade = 1;
            if (const double q = transparent_share(cl); q > 0) {
                if (!cl.emission.is_black()) add(beta * cl.emission);
                if (sampler.get2(alpha_base + alpha_tests++).u < q) {
                    if (++skips > max_skips) break;
                    beta *= cl.transparent * (1 / q);
                    if (beta.is_black() || !finite(beta)) break;
                    if (has_media_) stack.cross(hit, r.dir, *this);
                    const Vec3 o = offset_ray_origin(hit.p, hit.p_error, hit.ng, r.dir);
                    seg_dist += length(o - r.origin);
                    r.origin = o;
                    r.tmax = seg_end - seg_dist;
                    continue;
                }
                shade = 1 / (1 - q);
                cl.emission = Color();  // counted above
            }
            // Holdouts seen by the camera (Cycles' integrate_surface_holdout, before any
            // emission): a holdout object is transparent where it is not see-through and keeps
            // only its transparency (the pick above); a Holdout closure adds its weight and
            // ends the path when it is whole. Scaled like the BSDFs here (1 / (1 - q)).
            if (camera_view) {
                if (hit.object >= 0 && scene_.objects[static_cast<size_t>(hit.object)].holdout) {
                    const Color opaque(std::max(0.0, 1 - cl.transparent.r),
                                       std::max(0.0, 1 - cl.transparent.g),
                                       std::max(0.0, 1 - cl.transparent.b));
                    hold_out(opaque * shade);
                    break;
                }
                if (!cl.holdout.is_black()) {
                    hold_out(cl.holdout * shade);
                    if (cl.holdout.r >= 1 && cl.holdout.g >= 1 && cl.holdout.b >= 1) break;
                }
            }
            emission = cl.emission;
            const bool back = dot(hit.ng, r.dir) > 0;
            {
                const Vec3 ns = length_squared(cl.N) > 0 ? normalize(cl.N) : hit.n;
                set.set_smooth_normal(back ? -ns : ns);
            }
            // Filter Glossy (Cycles' blur_glossy): after a bounce of low pdf, microfacet
            // lobes are at least this rough (alpha; glint's roughness is its square root).
            double blur_alpha = 0;
            if (settings_.filter_glossy > 0 && !std::isinf(min_pdf)) {
                const double blur_pdf = settings_.filter_glossy * min_pdf;
                if (blur_pdf < 1) blur_alpha = std::sqrt(1 - blur_pdf) * 0.5;
            }
            for (int i = 0; i < cl.count(); ++i) {
                shader::Closure c = cl.items[i];
                if (blur_alpha > 0 && (c.kind == shader::ClosureKind::Principled ||
                                       c.kind == shader::ClosureKind::Glossy ||
                                       c.kind == shader::ClosureKind::Glass ||
                                       c.kind == shader::ClosureKind::Refraction)) {
                    c.roughness = std::max(c.roughness, std::sqrt(blur_alpha));
                    c.clearcoat_roughness = std::max(c.clearcoat_roughness, std::sqrt(blur_alpha));
                }
                Vec3 n = length_squared(c.N) > 0 ? normalize(c.N) : hit.n;
                if (back) n = -n;  // the closures' normals face the viewer; the set's the outside
                add_graph_closure(set, c, n, back ? -1.0 : 1.0, shade, diffuse_ancestor);
                albedo += c.weight * c.color;
            }
        } else {
            const SurfacePbr s = surface(hit, r.dir);
            if (s.alpha < 1 && sampler.get2(alpha_base + alpha_tests++).u >= s.alpha) {
                if (++skips > max_skips) break;
                if (has_media_) stack.cross(hit, r.dir, *this);
                const Vec3 o = offset_ray_origin(hit.p, hit.p_error, hit.ng, r.dir);
                seg_dist += length(o - r.origin);
                r.origin = o;
                r.tmax = seg_end - seg_dist;
                continue;
            }
            if (camera_view && hit.object >= 0 &&
                scene_.objects[static_cast<size_t>(hit.object)].holdout) {
                hold_out(Color(1, 1, 1));  // what the alpha coin left of it
                break;
            }
            emission = s.emission;
            albedo = s.bsdf.base;
            // Made once per material where the surface is constant (most hits): building one
            // costs Fresnel terms and a square root.
            set.add(row && row->constant_bsdf ? *row->constant_bsdf : Bsdf::principled(s.bsdf),
                    Color(1, 1, 1), hit.n, 1);
            if (!s.subsurface_radius.is_black())
                add_pov_subsurface(s, hit, r.dir, diffuse_ancestor, &set);
        }
        if (first && !first->hit) {
            first->hit = true;
            first->albedo = albedo.is_black() ? emission : albedo;
            first->normal = dot(hit.ng, r.dir) > 0 ? -hit.n : hit.n;
            first->depth = seg_dist + hit.t;
        }
        if (!emission.is_black()) {
            double w = 1;
            if (!specular && lights.emitter_object(hit.object)) {
                const double pl = lights.emitter_pdf(hit.object, prev_p, hit.p, hit.ng, emission);
                w = power_heuristic(prev_pdf, pl);
            }
            add(beta * emission * w);
        }
        if (depth >= settings_.max_depth || last_hit) break;
        if (set.count() == 0) break;

        // Next-event estimation.
        if (!set.all_delta() && lights.count() > 0) {
            auto light = [&](int slot, Sample2 u) {
                PathLightSample ls;
                if (!lights.sample(slot, hit.p, u, &ls)) return;
                // Which side a light is on is the shading normal's call, as in Cycles: the
                // BSDFs, each in its own shading frame, say whether they reflect or transmit.
                double bsdf_pdf = 0;
                const Color f = set.eval(ls.wi, &bsdf_pdf);
                if (f.is_black()) return;
                // The shadow ray starts in the media on the light's side of the surface.
                MediumStack light_stack = stack;
                if (has_media_ && (dot(ls.wi, hit.ng) > 0) != (dot(r.dir, hit.ng) < 0))
                    light_stack.cross(hit, ls.wi, *this);
                const uint32_t seed =
                    has_media_ ? static_cast<uint32_t>(volume_random() * 4294967296.0) : 0;
                const Color tr =
                    transmittance(offset_ray_origin(hit.p, hit.p_error, hit.ng, ls.wi), ls.wi,
                                  ls.dist, r.time, light_stack, seed, &rays);
                if (tr.is_black()) return;
                Color c = f * ls.value * tr;
                if (ls.environment) c *= environment(ls.wi);
                // (The photon integrator's camera pass stops here: no BSDF sample to weigh.)
                if (ls.pdf > 0 && !vp) c *= power_heuristic(ls.pdf, bsdf_pdf);
                add(beta * c);
            };
            if (lights.sample_all()) {
                for (int k = 0; k < lights.count(); ++k)
                    light(k, sampler.get2(base + 3 + static_cast<uint32_t>(k)));
            } else {
                const int k = std::min(lights.count() - 1, static_cast<int>(ua.v * lights.count()));
                light(k, sampler.get2(base + 3));
            }
        }

        // Continue the path by sampling the BSDFs: one 2D point picks the closure, the lobe and
        // the direction (ClosureSet::sample, Bsdf::sample); ul.v is the roulette's.
        const Sample2 ul = sampler.get2(base);
        const Sample2 ud = sampler.get2(base + 1);
        ClosureSample bs;
        const bool sampled = set.sample(ud.u, ud.v, &bs);
        if (vp && !set.all_delta() && !(sampled && bs.delta && !bs.bssrdf)) {
            // The photon integrator's visible point: the non-delta lobes were picked (chance
            // 1 - pd), so they stand for the whole of their share here.
            const double pd = set.delta_probability();
            if (pd < 1) {
                vp->found = true;
                vp->p = hit.p;
                vp->ng = hit.ng;
                vp->beta = beta * (1 / (1 - pd));
                vp->set = set;
                vp->depth = depth;
                vp->distance = travelled + seg_dist + hit.t;
            }
            break;
        }
        if (!sampled) break;
        ++scatterings;
        if (bs.bssrdf) {
            // A BSSRDF: a walk under the surface (no bounce of its own, as in Cycles), then the
            // loop's next vertex is where it leaves.
            beta *= bs.weight;
            exit_fresnel = bs.bssrdf->exit_fresnel;
            Vec3 out;
            if (beta.is_black() || !finite(beta) ||
                !subsurface_walk(geometry_, *bs.bssrdf, hit, -r.dir,
                                 [&] { return volume_random(); }, &beta, &exit_hit, &out, &rays))
                break;
            at_exit = true;
            camera_view = false;
            travelled += seg_dist + hit.t;
            seg_dist = 0;
            seg_end = kInfinity;
            r.origin = exit_hit.p;
            r.dir = -out;  // as if arriving from outside, so the exit is shaded outside
            continue;
        }
        // A bounce, or a refraction even at IOR 1 (Cycles' singular), ends the camera's view
        // of the world, but for Film > Transparent Glass's smooth enough transmissions
        // (Cycles' LABEL_TRANSMIT_TRANSPARENT).
        const double glass = settings_.film_transparent_glass;
        // (The threshold is a roughness, squared twice as Cycles squares it: roughness to
        // alpha, then alpha_x alpha_y.)
        camera_view = camera_view && glass >= 0 && !bs.reflected && !bs.diffuse &&
                      bs.roughness2 <= (glass * glass) * (glass * glass);
        beta *= bs.weight;
        if (bs.straight) {
            // Straight through an index-matched surface: like an alpha hole, not a bounce.
            // Shadow rays pass it too (transmittance), so what lies beyond keeps the MIS
            // weights of the last real bounce instead of being counted twice.
            if (++skips > max_skips || beta.is_black() || !finite(beta)) break;
            if (has_media_) stack.cross(hit, r.dir, *this);
            const Vec3 o = offset_ray_origin(hit.p, hit.p_error, hit.ng, r.dir);
            seg_dist += length(o - r.origin);
            r.origin = o;
            r.tmax = seg_end - seg_dist;
            continue;
        }
        specular = bs.delta;
        last_diffuse = !bs.delta && bs.diffuse;
        diffuse_ancestor = diffuse_ancestor || last_diffuse;
        last_reflected = bs.reflected;
        prev_pdf = bs.pdf;
        if (!bs.delta) min_pdf = std::min(min_pdf, bs.pdf);
        ++depth;
        // Cycles' kinds: a transmission whatever its lobe, else diffuse or glossy reflection.
        auto reached = [](int count, int limit) { return limit >= 0 && count > limit; };
        if (!bs.reflected)
            last_hit |= reached(++transmission_depth, settings_.transmission_bounces);
        else if (bs.diffuse)
            last_hit |= reached(++diffuse_depth, settings_.diffuse_bounces);
        else
            last_hit |= reached(++glossy_depth, settings_.glossy_bounces);
        if (depth >= settings_.rr_start) {
            const double p = std::min(1.0, std::sqrt(beta.max()));
            if (!(ul.v < p)) break;
            beta *= 1.0 / p;
        }
        if (beta.is_black() || !finite(beta)) break;
        const Vec3 wi = bs.wi;
        // A reflection the shading normal allows but that points into the surface (or a
        // refraction that stays outside) ends the path, as in Cycles: following it would
        // leak light through the geometry.
        if ((dot(wi, hit.ng) * dot(r.dir, hit.ng) < 0) != bs.reflected) break;
        if (has_media_ && !bs.reflected) stack.cross(hit, wi, *this);
        r.origin = offset_ray_origin(hit.p, hit.p_error, hit.ng, wi);
        r.dir = wi;
        r.tmax = seg_end = kInfinity;
        travelled += seg_dist + hit.t;
        seg_dist = 0;
        prev_p = hit.p;
    }
    // current_thread_index() is the worker's slot in its arena (0 outside one, as in tests).
    const int slot = std::max(0, tbb::this_task_arena::current_thread_index());
    rays_[static_cast<size_t>(slot) % rays_.size()].n.fetch_add(rays, std::memory_order_relaxed);
    if (!finite(L)) {
        nonfinite_.fetch_add(1, std::memory_order_relaxed);
        return Color();
    }
    return L;
}

}  // namespace glint::render
