// The path tracer's media (path.h): the volume stack, the media acting on a segment, and
// carrying paths and shadow rays through them.
#include <algorithm>
#include <cmath>

#include "render/integrators/path.h"

#include "render/prepare/containing.h"
#include "render/textures/vdb_grids.h"

namespace glint::render {
namespace {

// Collisions on one segment before the tracking gives up (a bound against runaway loops).
constexpr int kMaxCollisions = 1 << 20;
// The step of a volume marked Homogeneous in Cycles: one step per segment, shaded at its start.
constexpr double kHomogeneousStep = 1e300;

// A uniform number in [0, 1) from a 32-bit hash stream (ratio tracking of shadow rays).
double hash_uniform(uint32_t* seed) {
    *seed = hash_u32(*seed + 0x9e3779b9U);
    return static_cast<double>(*seed) * (1.0 / 4294967296.0);
}

bool finite(const Color& c) {
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}
double average(const Color& c) { return (c.r + c.g + c.b) / 3; }
double channel(const Color& c, int i) { return i == 0 ? c.r : i == 1 ? c.g : c.b; }
double power_heuristic(double a, double b) {
    const double a2 = a * a, b2 = b * b;
    if (!(a2 + b2 > 0)) return 0;
    if (std::isinf(a2)) return 1;
    return a2 / (a2 + b2);
}

}  // namespace

void PathIntegrator::MediumStack::cross(const Hit& hit, const Vec3& dir,
                                        const PathIntegrator& pi) {
    if (hit.object < 0) return;
    if (dot(dir, hit.ng) < 0) {
        // Entering (the geometric normal points out of the solid).
        if (count == kMax) return;  // deeper nesting than any sane scene: ignore it
        object[count] = hit.object;
        medium[count] = hit.material >= 0 ? pi.material_medium_[static_cast<size_t>(hit.material)]
                                          : -1;
        if (hit.material >= 0 && pi.material_grid_medium_[static_cast<size_t>(hit.material)] >= 0 &&
            pi.graphs_->grids(hit.object))
            medium[count] = pi.material_grid_medium_[static_cast<size_t>(hit.material)];
        // Blender's objects (node-graph materials) hold their volumes whatever encloses them.
        hollow[count] = (hit.flags & kHollow) != 0 ||
                        (hit.material >= 0 &&
                         pi.scene_.materials[static_cast<size_t>(hit.material)].graph >= 0);
        step[count] = medium[count] >= 0 &&
                              pi.media_[static_cast<size_t>(medium[count])].marched()
                          ? pi.volume_step(hit.object, hit.material)
                          : kInfinity;
        ++count;
        return;
    }
    for (int i = count - 1; i >= 0; --i) {
        if (object[i] != hit.object) continue;
        for (int j = i; j + 1 < count; ++j) {
            object[j] = object[j + 1];
            medium[j] = medium[j + 1];
            hollow[j] = hollow[j + 1];
            step[j] = step[j + 1];
        }
        --count;
        return;
    }
}

double PathIntegrator::volume_step(int object, int material) const {
    // Cycles: a Volume object's voxel (or its own step size, in object or world space), else a
    // tenth of the object's mean size, times the material's step rate and the scene's;
    // Homogeneous shades once per segment (a volume that reads grids never is).
    const scene::Material& m = scene_.materials[static_cast<size_t>(material)];
    const VdbGrids* grids = graphs_ ? graphs_->grids(object) : nullptr;
    if (m.volume_homogeneous && !grids) return kHomogeneousStep;
    double size = object >= 0 && static_cast<size_t>(object) < object_size_.size()
                      ? 0.1 * object_size_[static_cast<size_t>(object)] : 0.1;
    if (grids && grids->count() > 0) {
        const scene::Object::VolumeFile& vf = *scene_.objects[static_cast<size_t>(object)].volume_file;
        double s = grids->voxel_step();
        if (vf.step_size > 0 && !vf.object_space) {
            s = vf.step_size;
        } else if (vf.step_size > 0) {
            const Vec3 w = scene_.objects[static_cast<size_t>(object)].transform.vector(
                Vec3(vf.step_size, vf.step_size, vf.step_size));
            s = std::min({std::fabs(w.x), std::fabs(w.y), std::fabs(w.z)});
        }
        if (s > 0) size = s;
    }
    return size * m.volume_step_rate * settings_.volume_step_rate;
}

double PathIntegrator::world_volume_step() const {
    // Cycles 3.4 scales the world's step by the scene's step rate twice: once when it stores
    // it (Background::device_update), again where it reads it (volume_stack_step_size).
    if (scene_.world_volume_homogeneous) return kHomogeneousStep;
    return scene_.world_volume_step * settings_.volume_step_rate * settings_.volume_step_rate;
}

bool PathIntegrator::starts_at_camera(const Ray& r) const {
    const Vec3 off = r.origin - scene_.camera.location;
    if (off == Vec3(0, 0, 0)) return true;
    if (!(scene_.camera.clip_start > 0)) return false;
    const double along = dot(off, r.dir);
    return along > 0 && length(off - r.dir * along) <= 1e-9 * (1 + along);
}

int PathIntegrator::active_media(const MediumStack& stack, ActiveMedium* out,
                                 double* step) const {
    // As in POV-Ray's classic renderer: media act only while every object the ray is inside
    // is hollow (Ray::IsHollowRay); the atmosphere's then too.
    *step = kInfinity;
    for (int i = 0; i < stack.count; ++i)
        if (!stack.hollow[i]) return 0;
    int n = 0;
    for (int i = 0; i < stack.count; ++i)
        if (stack.medium[i] >= 0) {
            out[n++] = {&media_[static_cast<size_t>(stack.medium[i])], stack.object[i]};
            *step = std::min(*step, stack.step[i]);
        }
    if (world_medium_ >= 0) {
        out[n++] = {&media_[static_cast<size_t>(world_medium_)], -1};
        *step = std::min(*step, world_step_);
    }
    return n;
}

void PathIntegrator::medium_at(const ActiveMedium* media, int n, const Vec3& p,
                               const Vec3& dir, MediumPoint* out) const {
    if (n == 1) {
        media[0].medium->at(p, media[0].object, dir, out);
        return;
    }
    *out = MediumPoint{};
    for (int k = 0; k < n; ++k) {
        MediumPoint m;
        media[k].medium->at(p, media[k].object, dir, &m);
        out->sigma_a += m.sigma_a;
        out->emission += m.emission;
        for (int i = 0; i < m.lobe_count; ++i) {
            if (out->lobe_count < MediumPoint::kMaxLobes)
                out->lobes[out->lobe_count++] = m.lobes[i];
            else  // more lobes than room: the scattering still counts, in the last shape
                out->lobes[MediumPoint::kMaxLobes - 1].sigma_s += m.lobes[i].sigma_s;
        }
    }
}

Color PathIntegrator::media_transmittance(const ActiveMedium* media, int n, double step,
                                          const Vec3& origin, const Vec3& dir, double dist,
                                          uint32_t* seed) const {
    MediumPoint m;
    if (!std::isinf(step)) {
        // Cycles' volume_shadow_heterogeneous: steps from the origin (no offset), each shaded
        // once at one random offset.
        const int max_steps = settings_.volume_max_steps;
        if (std::isinf(dist)) return Color();
        double h = std::min(step, dist);
        if (dist > max_steps * h) h = dist / max_steps;
        const double shade = hash_uniform(seed);
        Color sum;
        double t = 0;
        for (int i = 0; i < max_steps; ++i) {
            const double nt = std::min(dist, (i + 1) * h);
            const double dt = nt - t;
            medium_at(media, n, origin + dir * (t + dt * shade), dir, &m);
            sum += m.sigma_t() * dt;
            if ((i & 7) == 0 && std::max(std::exp(-sum.r), std::max(std::exp(-sum.g),
                                                                   std::exp(-sum.b))) < 1e-6)
                return Color();
            t = nt;
            if (t >= dist) break;
        }
        return Color(std::exp(-sum.r), std::exp(-sum.g), std::exp(-sum.b));
    }
    bool homogeneous = true;
    double majorant = 0;
    for (int k = 0; k < n; ++k) {
        homogeneous = homogeneous && media[k].medium->homogeneous();
        majorant += media[k].medium->majorant();
    }
    if (!(majorant > 0)) return Color(1, 1, 1);
    if (homogeneous) {
        medium_at(media, n, origin, dir, &m);
        const Color st = m.sigma_t();
        auto tr = [dist](double s) { return s > 0 ? std::exp(-s * dist) : 1.0; };
        return Color(tr(st.r), tr(st.g), tr(st.b));
    }
    // Ratio tracking (Novak et al. 2014): the product of the null-collision probabilities at
    // tentative collisions drawn against the majorant; Russian roulette once it is small.
    Color t(1, 1, 1);
    double x = 0;
    for (int i = 0; i < kMaxCollisions; ++i) {
        x -= std::log(1 - hash_uniform(seed)) / majorant;
        if (!(x < dist)) return t;
        medium_at(media, n, origin + dir * x, dir, &m);
        const Color st = m.sigma_t();
        t *= Color(std::max(0.0, 1 - st.r / majorant), std::max(0.0, 1 - st.g / majorant),
                   std::max(0.0, 1 - st.b / majorant));
        const double mx = t.max();
        if (!(mx > 0)) return Color();
        if (mx < 0.1) {
            if (hash_uniform(seed) >= mx) return Color();
            t *= 1 / mx;
        }
    }
    return t;
}

int PathIntegrator::track(const ActiveMedium* act, int na, const Ray& r, double tmax,
                          VolumeRandom& random, Color* beta, Color* emitted, double* t_out,
                          MediumPoint* mp) const {
    bool homogeneous = true, emissive = false;
    double mu = 0;
    for (int k = 0; k < na; ++k) {
        homogeneous = homogeneous && act[k].medium->homogeneous();
        emissive = emissive || act[k].medium->emissive();
        mu += act[k].medium->majorant();
    }
    if (homogeneous) {
        // Closed forms: the emission integrated over the segment, and a distance drawn
        // exponentially in one channel, picked by throughput times albedo, with the pdf of
        // all the channels' choices together (one-sample spectral MIS, as Cycles does).
        medium_at(act, na, r.origin, r.dir, mp);
        const Color st = mp->sigma_t(), ss = mp->sigma_s();
        auto transmit = [&](double d) {
            auto one = [d](double s) { return s > 0 ? std::exp(-s * d) : 1.0; };
            return Color(one(st.r), one(st.g), one(st.b));
        };
        if (emissive && !mp->emission.is_black()) {
            auto integral = [tmax](double s) {
                if (!(s > 0)) return tmax;  // (infinite for an endless segment: dropped below)
                return std::isinf(tmax) ? 1 / s : -std::expm1(-s * tmax) / s;
            };
            const Color e = *beta * mp->emission *
                            Color(integral(st.r), integral(st.g), integral(st.b));
            if (finite(e)) *emitted += e;
        }
        if (ss.is_black()) {
            *beta *= transmit(tmax);
            return beta->is_black() ? 2 : 0;
        }
        double w[3];
        double total = 0;
        for (int c = 0; c < 3; ++c) {
            const double sc = channel(st, c);
            w[c] = std::fabs(channel(*beta, c)) * (sc > 0 ? channel(ss, c) / sc : 0);
            total += w[c];
        }
        for (int c = 0; c < 3; ++c) w[c] = total > 0 ? w[c] / total : 1.0 / 3;
        const double u = random();
        const int c = u < w[0] ? 0 : u < w[0] + w[1] ? 1 : 2;
        const double sc = channel(st, c);
        const double t = sc > 0 ? -std::log(1 - random()) / sc : kInfinity;
        if (t < tmax) {
            const Color tr = transmit(t);
            double pdf = 0;
            for (int k = 0; k < 3; ++k) pdf += w[k] * channel(st, k) * channel(tr, k);
            if (!(pdf > 0)) return 2;
            *beta *= ss * tr * (1 / pdf);
            *t_out = t;
            return 1;
        }
        const Color tr = transmit(tmax);
        double p = 0;
        for (int k = 0; k < 3; ++k) p += w[k] * channel(tr, k);
        if (!(p > 0)) return 2;
        *beta *= tr * (1 / p);
        return 0;
    }
    // Null-collision (delta) tracking against the summed majorants, weighted per channel:
    // each tentative collision adds the media's emission (the collision estimator), then
    // absorbs, scatters or passes with probabilities from the channel-averaged coefficients,
    // the weights correcting each channel.
    // Emission alone has no extinction to draw collisions by: some every few units of the
    // segment still integrate it.
    if (emissive && !std::isinf(tmax)) mu = std::max(mu, 8.0 / std::max(tmax, 1e-12));
    if (!(mu > 0)) return 0;
    double t = 0;
    for (int i = 0; i < kMaxCollisions; ++i) {
        t -= std::log(1 - random()) / mu;
        if (!(t < tmax)) return 0;
        medium_at(act, na, r.origin + r.dir * t, r.dir, mp);
        if (!mp->emission.is_black()) *emitted += *beta * mp->emission * (1 / mu);
        const Color ss = mp->sigma_s(), sa = mp->sigma_a;
        const Color sn(std::max(0.0, mu - sa.r - ss.r), std::max(0.0, mu - sa.g - ss.g),
                       std::max(0.0, mu - sa.b - ss.b));
        const double pa = average(sa) / mu, ps = average(ss) / mu, pn = average(sn) / mu;
        const double xi = random() * (pa + ps + pn);
        if (xi < pa) return 2;
        if (xi < pa + ps) {
            *beta *= ss * (1 / (mu * ps));
            *t_out = t;
            return 1;
        }
        *beta *= sn * (1 / (mu * pn));
        if (beta->is_black() || !finite(*beta)) return 2;
    }
    return 2;
}

int PathIntegrator::march(const ActiveMedium* act, int na, double step, const Ray& r,
                          double tmax, VolumeRandom& random, Color* beta, Color* emitted,
                          double* t_out, MediumPoint* mp) const {
    // Cycles 3.4's volume_step_init and volume_integrate_heterogeneous with distance sampling:
    // steps of `step` (at most volume_max_steps over the segment) starting at a random
    // fraction of the first, each shaded at one random offset within it and taken as
    // homogeneous: emission integrated in closed form, and a scattering distance drawn with
    // one random number carried from step to step, in the channel picked by throughput times
    // albedo.
    // An endless segment (a ray leaving into a world volume): Cycles' steps of FLT_MAX / max
    // steps shade the volume impossibly far away and let no light through; a Homogeneous one
    // shades once at the start and goes on below.
    if (std::isinf(tmax) && step < kHomogeneousStep) return 2;
    double h, shade, offset;
    int max_steps;
    if (step >= kHomogeneousStep) {
        h = tmax;
        shade = 0;
        offset = 1;
        max_steps = 1;
    } else {
        max_steps = settings_.volume_max_steps;
        h = std::min(step, tmax);
        if (tmax > max_steps * h) h = tmax / max_steps;
        shade = random();
        offset = random();
    }
    double rscatter = random();
    const double rphase = random();
    double t0 = 0;
    for (int i = 0; i < max_steps; ++i) {
        const double t1 = std::min(tmax, (i + offset) * h);
        const double dt = t1 - t0;
        medium_at(act, na, r.origin + r.dir * (t0 + dt * shade), r.dir, mp);
        const Color st = mp->sigma_t(), ss = mp->sigma_s();
        auto transmit = [&st](double d) {
            auto one = [d](double s) { return s > 0 ? std::exp(-s * d) : 1.0; };
            return Color(one(st.r), one(st.g), one(st.b));
        };
        const Color tr = transmit(dt);
        if (!mp->emission.is_black()) {
            // (No extinction over an endless step: the emission would be infinite; none.)
            auto integral = [dt](double s, double trc) {
                return s > 0 ? (1 - trc) / s : std::isinf(dt) ? 0.0 : dt;
            };
            *emitted += *beta * mp->emission *
                        Color(integral(st.r, tr.r), integral(st.g, tr.g), integral(st.b, tr.b));
        }
        if (!ss.is_black()) {
            double w[3], total = 0;
            for (int c = 0; c < 3; ++c) {
                const double sc = channel(st, c);
                w[c] = std::fabs(channel(*beta, c)) * (sc > 0 ? channel(ss, c) / sc : 0);
                total += w[c];
            }
            for (int c = 0; c < 3; ++c) w[c] = total > 0 ? w[c] / total : 1.0 / 3;
            const int c = rphase < w[0] ? 0 : rphase < w[0] + w[1] ? 1 : 2;
            const double sample_tr = channel(tr, c);
            if (1 - rscatter >= sample_tr) {
                const double nd = -std::log(1 - rscatter) / channel(st, c);
                const Color ntr = transmit(nd);
                double pdf = 0;
                for (int k = 0; k < 3; ++k) pdf += w[k] * channel(st, k) * channel(ntr, k);
                if (!(pdf > 0)) return 2;
                *beta *= ss * ntr * (1 / pdf);
                *t_out = t0 + nd;
                return 1;
            }
            double pdf = 0;
            for (int k = 0; k < 3; ++k) pdf += w[k] * channel(tr, k);
            if (!(pdf > 0)) return 2;
            *beta *= tr * (1 / pdf);
            rscatter = 1 - (1 - rscatter) / sample_tr;
        } else {
            *beta *= tr;
        }
        if (!finite(*beta) || beta->max() < 1e-6) return 2;  // VOLUME_THROUGHPUT_EPSILON
        t0 = t1;
        if (t0 >= tmax) break;
    }
    return 0;
}

double PathIntegrator::distance_pdf(const Color& beta0, const MediumPoint& m, double t) {
    // As track() picks its channel: by throughput times albedo.
    const Color st = m.sigma_t(), ss = m.sigma_s();
    double w[3], total = 0;
    for (int c = 0; c < 3; ++c) {
        const double sc = channel(st, c);
        w[c] = std::fabs(channel(beta0, c)) * (sc > 0 ? channel(ss, c) / sc : 0);
        total += w[c];
    }
    double pdf = 0;
    for (int c = 0; c < 3; ++c) {
        const double sc = channel(st, c);
        pdf += (total > 0 ? w[c] / total : 1.0 / 3) * sc * std::exp(-sc * t);
    }
    return pdf;
}

Color PathIntegrator::equiangular_direct(const ActiveMedium* act, int na, const Ray& r,
                                         double tmax, const Color& beta0,
                                         const MediumStack& stack, const PixelSampler& sampler,
                                         uint32_t base, VolumeRandom& random,
                                         uint64_t* rays) const {
    const PathLights& lights = *lights_;
    MediumPoint m;
    medium_at(act, na, r.origin, r.dir, &m);
    const Color ss = m.sigma_s(), st = m.sigma_t();
    if (ss.is_black()) return Color();
    Color sum;
    auto light = [&](int slot, Sample2 u) {
        // Where the light is (point and spot lights: a fixed point, no pdf to hit them).
        PathLightSample at;
        if (!lights.sample(slot, r.origin, u, &at) || at.pdf > 0 || std::isinf(at.dist)) return;
        const Vec3 q = r.origin + at.wi * at.dist;
        double t, pdf;
        if (!equiangular_sample(r.origin, r.dir, tmax, q, random(), &t, &pdf)) return;
        const Vec3 p = r.origin + r.dir * t;
        PathLightSample ls;
        if (!lights.sample(slot, p, u, &ls)) return;
        const double ph = phase_eval(m, -r.dir, ls.wi);
        if (!(ph > 0)) return;
        const Color tr = transmittance(p, ls.wi, ls.dist, r.time, stack,
                                       static_cast<uint32_t>(random() * 4294967296.0), rays);
        if (tr.is_black()) return;
        const Color transmit(std::exp(-st.r * t), std::exp(-st.g * t), std::exp(-st.b * t));
        const double w = power_heuristic(pdf, distance_pdf(beta0, m, t));
        sum += beta0 * transmit * ss * ls.value * tr * (ph * w / pdf);
    };
    if (lights.sample_all()) {
        for (int k = 0; k < lights.count(); ++k)
            light(k, sampler.get2(base + 3 + static_cast<uint32_t>(k)));
    } else {
        const Sample2 ul = sampler.get2(base + 2);
        light(std::min(lights.count() - 1, static_cast<int>(ul.v * lights.count())),
              sampler.get2(base + 3));
    }
    return finite(sum) ? sum : Color();
}

void PathIntegrator::setup_media() {
    // Media: each material's interior media (POV-Ray) or volume shader (Blender) become one
    // medium, the atmosphere's or the world's volume another.
    sslt_mm_ = scene_.global.subsurface ? scene_.global.mm_per_unit : 0;
    material_medium_.assign(scene_.materials.size(), -1);
    material_grid_medium_.assign(scene_.materials.size(), -1);
    bool volume_objects = false;
    for (const scene::Object& o : scene_.objects) volume_objects |= o.volume_file.has_value();
    for (size_t m = 0; m < scene_.materials.size(); ++m) {
        const auto& media = scene_.materials[m].interior.media;
        const PathMaterial* row = materials_.path(static_cast<int>(m));
        const shader::ShaderProgram* volume = row && row->program && row->program->has_volume()
                                                  ? row->program : nullptr;
        if (media.empty() && !volume) continue;
        material_medium_[m] = static_cast<int>(media_.size());
        if (volume && volume->volume_constant()) {
            shader::VolumeClosures v;
            volume->evaluate_volume(shader::ShaderGlobals{}, &v);
            media_.emplace_back(PathMedium::from_closures(v));
            // In a Volume object it reads the grids, or is scaled with the object: marched
            // there (Cycles' volume_is_homogeneous, object_volume_density), the same
            // everywhere else.
            if (volume->volume_grids() || volume_objects) {
                material_grid_medium_[m] = static_cast<int>(media_.size());
                media_.emplace_back(volume, graphs_);
            }
        } else if (volume) {
            media_.emplace_back(volume, graphs_);
        } else {
            media_.emplace_back(media, &pigments_);
        }
    }
    const shader::ShaderProgram* world_graph = graphs_ ? graphs_->world() : nullptr;
    if (!scene_.media.empty()) {
        world_medium_ = static_cast<int>(media_.size());
        media_.emplace_back(scene_.media, &pigments_);
    } else if (world_graph && world_graph->has_volume()) {
        world_medium_ = static_cast<int>(media_.size());
        if (world_graph->volume_constant()) {
            shader::VolumeClosures v;
            world_graph->evaluate_volume(shader::ShaderGlobals{}, &v);
            media_.emplace_back(PathMedium::from_closures(v));
        } else {
            media_.emplace_back(world_graph, graphs_);
            world_step_ = world_volume_step();
        }
    }
    // The objects' sizes, for the steps of volumes ray marched inside them.
    bool marched = false;
    for (const PathMedium& m : media_) marched = marched || m.marched();
    if (marched) {
        object_size_.assign(scene_.objects.size(), 1.0);
        for (size_t o = 0; o < scene_.objects.size(); ++o) {
            const auto* ref = std::get_if<scene::MeshRef>(&scene_.objects[o].shape);
            if (!ref || ref->mesh < 0 || static_cast<size_t>(ref->mesh) >= scene_.meshes.size())
                continue;
            const std::vector<Vec3>& pos = scene_.meshes[static_cast<size_t>(ref->mesh)].positions;
            if (pos.empty()) continue;
            // Cycles' Object::bounds: the mesh's bounds, their corners transformed.
            Vec3 lo = pos[0], hi = pos[0];
            for (const Vec3& q : pos) lo = min(lo, q), hi = max(hi, q);
            const Transform& t = scene_.objects[o].transform;
            Vec3 wlo(kInfinity, kInfinity, kInfinity), whi = -wlo;
            for (int k = 0; k < 8; ++k) {
                const Vec3 c = t.point(Vec3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y,
                                            k & 4 ? hi.z : lo.z));
                wlo = min(wlo, c);
                whi = max(whi, c);
            }
            const Vec3 size = whi - wlo;
            object_size_[o] = (size.x + size.y + size.z) / 3;
        }
    }
    has_media_ = !media_.empty();
    if (has_media_)
        for (const Containing& c : objects_containing_camera(scene_, geometry_)) {
            Hit h;
            h.object = c.object;
            h.material = c.material;
            h.flags = c.hollow ? kHollow : 0u;
            h.ng = Vec3(0, 0, 1);
            camera_stack_.cross(h, Vec3(0, 0, -1), *this);  // entering it
        }
}

}  // namespace glint::render
