#include "render/gi/sppm.h"

#include <algorithm>
#include <atomic>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "core/float.h"
#include "render/film/driver.h"
#include "render/film/pixel_filter.h"
#include "render/lights/light_emission.h"

namespace glint::render {
namespace {

// A photon where it landed after at least one bounce.
struct StoredPhoton {
    Vec3 p;
    Vec3 wi;      // unit, back towards where it came from
    Color power;  // flux
    int depth;    // bounces before it landed
};

// A kd-tree over the photons of one pass, the median of each range at its middle; a radius
// query visits every photon within it.
class PhotonTree {
public:
    explicit PhotonTree(std::vector<StoredPhoton> photons) : p_(std::move(photons)) {
        axis_.assign(p_.size(), 0);
        build(0, p_.size());
    }
    template <class F>
    void within(const Vec3& q, double r, F&& visit) const {
        if (!p_.empty()) query(0, p_.size(), q, r, r * r, visit);
    }

private:
    static double coord(const Vec3& v, int a) { return a == 0 ? v.x : a == 1 ? v.y : v.z; }
    void build(size_t lo, size_t hi) {
        if (hi - lo <= 1) return;
        Bounds3 b;
        for (size_t i = lo; i < hi; ++i) b.extend(p_[i].p);
        const Vec3 d = b.diagonal();
        const int a = d.x >= d.y && d.x >= d.z ? 0 : d.y >= d.z ? 1 : 2;
        const size_t mid = (lo + hi) / 2;
        std::nth_element(p_.begin() + lo, p_.begin() + mid, p_.begin() + hi,
                         [a](const StoredPhoton& x, const StoredPhoton& y) {
                             return coord(x.p, a) < coord(y.p, a);
                         });
        axis_[mid] = static_cast<uint8_t>(a);
        build(lo, mid);
        build(mid + 1, hi);
    }
    template <class F>
    void query(size_t lo, size_t hi, const Vec3& q, double r, double r2, F& visit) const {
        while (hi > lo) {
            const size_t mid = (lo + hi) / 2;
            const StoredPhoton& ph = p_[mid];
            if (length_squared(ph.p - q) <= r2) visit(ph);
            if (hi - lo == 1) return;
            const double d = coord(q, axis_[mid]) - coord(ph.p, axis_[mid]);
            // The near side by iteration, the far side (if the sphere reaches it) by recursion.
            if (d < 0) {
                if (d > -r || d * d <= r2) query(mid + 1, hi, q, r, r2, visit);
                hi = mid;
            } else {
                if (d < r || d * d <= r2) query(lo, mid, q, r, r2, visit);
                lo = mid + 1;
            }
        }
    }
    std::vector<StoredPhoton> p_;
    std::vector<uint8_t> axis_;
};

float sanitize(double v) {
    if (!(v > 0.0)) return 0.0f;
    if (v > FLT_MAX) return FLT_MAX;
    return static_cast<float>(v);
}

bool finite(const Color& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }

// Each pixel's progressive statistics (Hachisuka and Jensen 2009, section 4).
struct PixelStat {
    double radius = 0;  // 0 until the pixel's first visible point
    double n = 0;       // photons accumulated (after the alpha reduction)
    Color tau;          // flux gathered, rescaled to the current radius
    Color direct;       // the camera passes' own light (emission, direct light), summed
};

constexpr long kChunk = 1024;        // photons per parallel task
constexpr int kMaxPassThroughs = 64;  // alpha holes a photon may cross
// Sampler pairs of one photon: 0 the light, 1 the start, 2 the direction, then per surface
// (the alpha coin and roulette) and (the BSDF sample).
constexpr uint32_t kPhotonPairsPerHit = 2;

}  // namespace

SppmResult render_sppm(const PreparedScene& prepared, const PathIntegrator& path,
                       const RenderOptions& options, const SppmSettings& settings,
                       Diagnostics& diag) {
    const auto start = std::chrono::steady_clock::now();
    if (const std::string why = path.photon_limits(); !why.empty())
        throw Error(ErrorKind::Render, {},
                    "--integrator sppm does not render " + why +
                        " yet; render this scene with --integrator path");
    const Geometry& geometry = *prepared.geometry;
    const Camera& camera = prepared.camera;
    const Region region = options.region.empty()
                              ? Region{0, 0, options.width, options.height}
                              : options.region;
    const int fw = region.width(), fh = region.height();
    const size_t pixels = static_cast<size_t>(fw) * fh;
    const PixelFilter filter(options.pixel_filter, options.filter_width);
    const Shutter* shutter = prepared.shutter.active() ? &prepared.shutter : nullptr;

    // The sphere around the scene that parallel lights and the environment shine through:
    // the bounds of its finite objects and the camera (infinite planes would make it endless
    // and spread the photons thin), or with none, what the camera sees through every fourth
    // pixel centre.
    Bounds3 bounds = geometry.finite_bounds();
    if (!bounds.empty()) {
        if (const std::optional<Ray> ray = camera.generate(0.5 * options.width,
                                                           0.5 * options.height))
            bounds.extend(ray->origin);
    } else {
        for (int y = 0; y < options.height; y += 4)
            for (int x = 0; x < options.width; x += 4) {
                const std::optional<Ray> ray = camera.generate(x + 0.5, y + 0.5);
                if (!ray) continue;
                bounds.extend(ray->origin);
                Hit h;
                if (geometry.intersect(*ray, &h)) bounds.extend(h.p);
            }
    }
    const Vec3 center = bounds.empty() ? Vec3() : bounds.centroid();
    const double radius = bounds.empty() ? 1.0 : std::max(1e-6, 0.5 * length(bounds.diagonal()));
    const LightEmission emission(prepared.scene, path.lights(),
                                 [&path](const Vec3& d) { return path.environment_radiance(d); },
                                 center, radius * 1.001);
    if (const std::string why = emission.unsupported(); !why.empty())
        throw Error(ErrorKind::Render, {},
                    "--integrator sppm cannot shoot photons from " + why +
                        " yet; render this scene with --integrator path");

    // Emitting objects light sampling leaves to BSDF hits (boxes, CSG parts, ...): no photon
    // leaves them and no visible point samples them, so their light reaches only the camera.
    {
        const std::vector<Color> emission = prepared.materials.emission();
        auto emits = [&](const scene::Object& o, const auto& self) -> bool {
            if (o.material >= 0 && static_cast<size_t>(o.material) < emission.size() &&
                !emission[static_cast<size_t>(o.material)].is_black())
                return true;
            if (const auto* csg = std::get_if<scene::Csg>(&o.shape))
                for (const scene::Object& c : csg->children)
                    if (self(c, self)) return true;
            return false;
        };
        int dark = 0;
        const scene::Object* first = nullptr;
        for (size_t i = 0; i < prepared.scene.objects.size(); ++i) {
            const scene::Object& o = prepared.scene.objects[i];
            if (emits(o, emits) && !path.lights().emitter_object(static_cast<int>(i))) {
                if (!first) first = &o;
                ++dark;
            }
        }
        if (first)
            diag.warning(first->loc,
                         (dark > 1 ? std::to_string(dark) + " emitting objects, this the first, "
                                                            "cannot be light-sampled"
                                   : std::string("this emitting object cannot be light-sampled")) +
                             " (only emitting triangles, meshes, spheres and discs can): "
                             "--integrator sppm shows the emission where the camera sees it but "
                             "lights nothing with it; --integrator path renders that light");
    }

    SppmResult result;
    const long photons = settings.photons > 0
                             ? settings.photons
                             : static_cast<long>(options.width) * options.height;
    result.photons = photons;
    const int passes = std::max(1, settings.passes);
    const int max_depth = std::max(0, settings.max_depth);
    std::vector<PixelStat> stat(pixels);
    std::atomic<bool> subsurface{false};

    const int threads = options.threads > 0 ? options.threads : tbb::task_arena::automatic;
    tbb::task_arena arena(threads);
    auto cancelled = [&options] {
        return options.cancel && options.cancel->load(std::memory_order_relaxed);
    };
    // The image after `n` passes of `photons` photons each.
    auto resolve = [&](int n) {
        Image img;
        img.width = fw;
        img.height = fh;
        img.rgba.assign(pixels * 4, 0.0f);
        const double shot = static_cast<double>(n) * static_cast<double>(photons);
        for (size_t i = 0; i < pixels; ++i) {
            const PixelStat& s = stat[i];
            Color c = s.direct * (1.0 / n);
            if (s.radius > 0) c += s.tau * (1.0 / (shot * kPi * s.radius * s.radius));
            img.rgba[i * 4 + 0] = sanitize(c.r);
            img.rgba[i * 4 + 1] = sanitize(c.g);
            img.rgba[i * 4 + 2] = sanitize(c.b);
            img.rgba[i * 4 + 3] = 1.0f;
        }
        return img;
    };
    auto interrupt = [&](int done) {
        auto partial = std::make_shared<PartialRender>();
        partial->spp_requested = passes;
        if (done > 0) {
            partial->film.image = resolve(done);
            partial->samples_per_pixel = done;
        } else {
            partial->film.image.width = fw;
            partial->film.image.height = fh;
            partial->film.image.rgba.assign(pixels * 4, 0.0f);
        }
        partial->tiles_total = 1;
        partial->tiles_done = done > 0 ? 1 : 0;
        throw Interrupted(std::move(partial));
    };

    for (int pass = 0; pass < passes; ++pass) {
        // Photons: chunk by chunk, each photon from its own sampler (the pass scrambles the
        // sequence), kept in photon order.
        const long chunks = (photons + kChunk - 1) / kChunk;
        std::vector<std::vector<StoredPhoton>> stored(static_cast<size_t>(chunks));
        std::atomic<bool> stop{false};
        arena.execute([&] {
            tbb::parallel_for(
                tbb::blocked_range<long>(0, chunks, 1),
                [&](const tbb::blocked_range<long>& range) {
                    for (long c = range.begin(); c != range.end(); ++c) {
                        if (cancelled()) {
                            stop = true;
                            return;
                        }
                        std::vector<StoredPhoton>& out = stored[static_cast<size_t>(c)];
                        const long end = std::min(photons, (c + 1) * kChunk);
                        for (long j = c * kChunk; j < end; ++j) {
                            const PixelSampler ps(pass, -0x5eed, static_cast<uint32_t>(j),
                                                  options.seed);
                            EmissionSample es;
                            if (!emission.sample(ps.get1(0), ps.get2(1), ps.get2(2), &es))
                                continue;
                            Color power = es.power;
                            Ray r;
                            r.origin = es.origin;
                            r.dir = es.dir;
                            int bounces = 0, skips = 0;
                            bool first = true;
                            double flight = 0;  // from the light to the first surface
                            for (uint32_t k = 0;; ++k) {
                                Hit hit;
                                if (!geometry.intersect(r, &hit)) break;
                                flight += hit.t;
                                const uint32_t base = 3 + k * kPhotonPairsPerHit;
                                const Sample2 uc = ps.get2(base);
                                PhotonSurface surf;
                                if (!path.photon_surface(hit, r.dir, uc.u, &surf)) break;
                                if (surf.pass) {
                                    power *= surf.pass_weight;
                                    if (++skips > kMaxPassThroughs || power.is_black()) break;
                                    r.origin =
                                        offset_ray_origin(hit.p, hit.p_error, hit.ng, r.dir);
                                    continue;
                                }
                                if (first) {
                                    // Where the light's own reach ends (through alpha holes).
                                    power *= emission.first_flight(es.pov_light, flight);
                                    first = false;
                                    if (power.is_black() || !finite(power)) break;
                                }
                                if (bounces > 0 && !surf.set.all_delta())
                                    out.push_back({hit.p, -r.dir, power, bounces});
                                // A bounce stored after this one must stay within max_depth
                                // counting the visible point's own bounce.
                                if (bounces + 1 > max_depth - 1) break;
                                const Sample2 ud = ps.get2(base + 1);
                                ClosureSample bs;
                                if (!surf.set.sample(ud.u, ud.v, &bs)) break;
                                if (bs.bssrdf) {
                                    subsurface = true;
                                    break;
                                }
                                if ((dot(bs.wi, hit.ng) * dot(r.dir, hit.ng) < 0) != bs.reflected)
                                    break;
                                const Color next = power * bs.weight;
                                if (!bs.straight) {
                                    ++bounces;
                                    // Roulette keeps the flux about constant (pbrt's SPPM).
                                    const double before = power.max(), after = next.max();
                                    const double q = before > 0 ? std::max(0.0, 1 - after / before)
                                                                : 1.0;
                                    if (uc.v < q) break;
                                    power = next * (1 / (1 - q));
                                } else {
                                    if (++skips > kMaxPassThroughs) break;
                                    power = next;
                                }
                                if (power.is_black() || !finite(power)) break;
                                r.origin = offset_ray_origin(hit.p, hit.p_error, hit.ng, bs.wi);
                                r.dir = bs.wi;
                                r.tmax = kInfinity;
                            }
                        }
                    }
                },
                tbb::simple_partitioner());
        });
        if (stop || cancelled()) interrupt(pass);
        std::vector<StoredPhoton> all;
        for (auto& chunk : stored) all.insert(all.end(), chunk.begin(), chunk.end());
        result.stored += all.size();
        const PhotonTree tree(std::move(all));
        if (options.progress) options.progress((pass + 0.5) / passes);

        // Camera paths, row by row, each pixel gathering at its visible point.
        arena.execute([&] {
            tbb::parallel_for(
                tbb::blocked_range<int>(region.y0, region.y1, 1),
                [&](const tbb::blocked_range<int>& rows) {
                    for (int y = rows.begin(); y != rows.end(); ++y) {
                        if (cancelled()) {
                            stop = true;
                            return;
                        }
                        for (int x = region.x0; x < region.x1; ++x) {
                            PixelStat& s = stat[static_cast<size_t>(y - region.y0) * fw +
                                                (x - region.x0)];
                            const PixelSampler ps(x, y, static_cast<uint32_t>(pass), options.seed);
                            const std::optional<Ray> ray =
                                path_camera_ray(camera, filter, shutter, ps, x, y,
                                                static_cast<uint32_t>(pass));
                            if (!ray) continue;
                            VisiblePoint vp;
                            const Color l = path.li(*ray, ps, nullptr, &vp);
                            if (finite(l)) s.direct += l;
                            if (!vp.found) continue;
                            if (vp.set.has_bssrdf()) subsurface = true;
                            if (s.radius == 0) {
                                // The pixel's footprint at the visible point's distance.
                                const std::optional<Ray> a = camera.generate(x + 0.5, y + 0.5);
                                std::optional<Ray> b = camera.generate(x + 1.5, y + 0.5);
                                if (!b) b = camera.generate(x - 0.5, y + 0.5);
                                double foot = 0;
                                if (a && b)
                                    foot = length(a->origin - b->origin) +
                                           vp.distance *
                                               length(normalize(a->dir) - normalize(b->dir));
                                if (!(foot > 0) || !std::isfinite(foot))
                                    foot = 1e-3 * radius;
                                s.radius = settings.radius * foot;
                            }
                            const int reach = max_depth - 1 - vp.depth;
                            Color phi;
                            double m = 0;
                            tree.within(vp.p, s.radius, [&](const StoredPhoton& ph) {
                                if (ph.depth > reach) return;
                                double pdf;
                                const Color f = vp.set.eval(ph.wi, &pdf);
                                m += 1;
                                if (f.is_black()) return;
                                const double cos_g = std::max(std::fabs(dot(ph.wi, vp.ng)), 1e-3);
                                phi += f * ph.power * (1 / cos_g);
                            });
                            if (m == 0) continue;
                            // Progressive update: keep alpha of the new photons and shrink
                            // the radius so the density stays.
                            const double n_new = s.n + settings.alpha * m;
                            const double r_new = s.radius * std::sqrt(n_new / (s.n + m));
                            Color tau = s.tau + vp.beta * phi;
                            if (!finite(tau)) tau = s.tau;
                            s.tau = tau * ((r_new * r_new) / (s.radius * s.radius));
                            s.n = n_new;
                            s.radius = r_new;
                        }
                    }
                },
                tbb::simple_partitioner());
        });
        if (stop || cancelled()) interrupt(pass);
        result.passes = pass + 1;
        if (options.progress) options.progress((pass + 1.0) / passes);
        if (options.time_limit > 0 &&
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >=
                options.time_limit)
            break;
    }
    if (subsurface)
        diag.warning({}, "--integrator sppm does not render subsurface scattering yet: the "
                         "surfaces with it lack their subsurface light (use --integrator path)");
    result.image = resolve(result.passes);
    return result;
}

}  // namespace glint::render
