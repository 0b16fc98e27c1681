#include "render/render.h"

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "render/film/driver.h"
#include "render/gi/sppm.h"
#include "render/integrators/path.h"
#include "render/integrators/whitted.h"
#include "render/prepare/prepared_scene.h"
#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool has_blob_component_textures(const scene::Object& o) {
    if (const auto* blob = std::get_if<scene::Blob>(&o.shape))
        for (const scene::BlobComponent& c : blob->components)
            if (c.material >= 0) return true;
    if (const auto* csg = std::get_if<scene::Csg>(&o.shape))
        for (const scene::Object& c : csg->children)
            if (has_blob_component_textures(c)) return true;
    return false;
}

// What the classic renderer draws and the path tracer (and the photon integrator, which
// shades with it) does not: said once each, never dropped silently.
void warn_classic_only(const scene::Scene& scene, Diagnostics& diag) {
    std::string what;
    auto add = [&](bool found, const char* name) {
        if (found) what += std::string(what.empty() ? "" : "; ") + name;
    };
    bool groups = false, projected = false;
    for (const scene::Light& l : scene.lights) {
        groups = groups || l.group >= 0;
        projected = projected || l.projected_through;
    }
    bool blob_textures = false;
    for (const scene::Object& o : scene.objects)
        blob_textures = blob_textures || has_blob_component_textures(o);
    bool inside_textures = false;
    for (const scene::Material& m : scene.materials)
        inside_textures = inside_textures || !m.interior_texture.empty();
    add(groups, "light_group (every light lights every object)");
    add(projected, "projected_through (the light shines everywhere)");
    add(blob_textures, "blob component textures (the blob's own texture everywhere)");
    add(inside_textures, "interior_texture (the outside texture on both sides)");
    if (!what.empty())
        diag.warning({}, "only --integrator whitted renders " + what);
}

}  // namespace

RenderResult render(const scene::Scene& scene, const RenderOptions& options, Diagnostics& diag) {
    auto t0 = std::chrono::steady_clock::now();
    RenderResult result;
    // Prepare: the IR becomes what the integrators read (prepare/prepared_scene.h).
    // The photon integrator shades with the path tracer's materials and lights.
    RenderOptions prepare_options = options;
    if (options.integrator == IntegratorKind::Sppm) prepare_options.integrator = IntegratorKind::Path;
    std::unique_ptr<PreparedScene> prepared = prepare(scene, prepare_options, diag);
    result.features = prepared->features;
    if (options.integrator != IntegratorKind::Whitted) warn_classic_only(scene, diag);
    if (options.integrator == IntegratorKind::Sppm) {
        // Cycles' render settings a Blender scene brings that the photons do not follow.
        std::string ignored;
        auto ignore = [&](bool set, const char* what) {
            if (set) ignored += std::string(ignored.empty() ? "" : ", ") + what;
        };
        ignore(options.film_transparent, "Film > Transparent");
        ignore(options.clamp_direct > 0 || options.clamp_indirect > 0, "clamping");
        ignore(options.filter_glossy > 0, "Filter Glossy");
        ignore(options.adaptive, "adaptive sampling");
        ignore(options.diffuse_bounces >= 0 || options.glossy_bounces >= 0 ||
                   options.transmission_bounces >= 0 || options.transparent_bounces >= 0,
               "bounce limits by kind");
        if (!ignored.empty())
            diag.warning({}, "--integrator sppm ignores " + ignored +
                                 " (only --max-depth limits its paths)");
        PathSettings ps;
        ps.max_depth = std::max(0, options.max_depth);
        PathIntegrator path(*prepared, ps);
        result.prepare_seconds = seconds_since(t0);
        auto t1 = std::chrono::steady_clock::now();
        SppmSettings ss;
        ss.max_depth = ps.max_depth;
        ss.passes = options.spp;
        ss.photons = options.photons;
        ss.radius = options.photon_radius;
        SppmResult r = render_sppm(*prepared, path, options, ss, diag);
        diag.info("sppm: " + std::to_string(r.passes) + " passes of " +
                  std::to_string(r.photons) + " photons, " + std::to_string(r.stored) +
                  " stored");
        result.image = std::move(r.image);
        result.samples_per_pixel = r.passes;
        result.nonfinite_paths = path.nonfinite();
        result.rays = path.rays();
        result.render_seconds = seconds_since(t1);
        return result;
    }
    if (options.integrator == IntegratorKind::Path) {
        PathSettings ps;
        ps.max_depth = std::max(0, options.max_depth);
        ps.clamp_direct = options.clamp_direct;
        ps.clamp_indirect = options.clamp_indirect;
        ps.filter_glossy = options.filter_glossy;
        ps.light_tree = options.light_tree;
        ps.diffuse_bounces = options.diffuse_bounces;
        ps.glossy_bounces = options.glossy_bounces;
        ps.transmission_bounces = options.transmission_bounces;
        ps.volume_bounces = options.volume_bounces;
        ps.transparent_bounces = options.transparent_bounces;
        ps.film_transparent = options.film_transparent;
        ps.film_transparent_glass = options.film_transparent_glass;
        ps.volume_step_rate = options.volume_step_rate;
        ps.volume_max_steps = options.volume_max_steps;
        // The film carries alpha where something can make the camera's view transparent: a
        // transparent film, a holdout object or a Holdout closure (as in Cycles, with or
        // without the transparent film). Otherwise alpha stays 1 and the file has none.
        RenderOptions film_options = options;
        film_options.alpha = options.alpha || options.film_transparent ||
                             prepared->materials.any_holdout();
        for (const scene::Object& o : scene.objects) film_options.alpha |= o.holdout;
        result.alpha = film_options.alpha;
        PathIntegrator path(*prepared, ps);
        result.prepare_seconds = seconds_since(t0);
        auto t1 = std::chrono::steady_clock::now();
        const uint32_t seed = options.seed;
        PathRadianceFn radiance = [&path, seed](const Ray& ray, const SampleId& id,
                                                FirstHit* first) {
            return path.li(ray, PixelSampler(id.x, id.y, id.index, seed), first);
        };
        PathFilm film;
        result.samples_per_pixel = run_path_tiles(prepared->camera, film_options, radiance,
                                                   &film, &prepared->shutter);
        result.image = std::move(film.image);
        result.albedo = std::move(film.albedo);
        result.normal = std::move(film.normal);
        result.depth = std::move(film.depth);
        result.variance = std::move(film.variance);
        result.nonfinite_paths = path.nonfinite();
        result.rays = path.rays();
        result.render_seconds = seconds_since(t1);
        return result;
    }
    Whitted whitted(*prepared);
    DriverSettings settings;
    if (scene.global.assumed_gamma) settings.working_gamma = *scene.global.assumed_gamma;
    result.prepare_seconds = seconds_since(t0);

    auto t1 = std::chrono::steady_clock::now();
    if (scene.global.photons) {
        whitted.shoot_photons(options.threads);
        diag.info("photons: " + std::to_string(whitted.photons()->size()) +
                  " stored, gather radius " + std::to_string(whitted.photons()->gather_radius()));
    }
    Radiosity* radiosity = whitted.radiosity();
    if (radiosity) {
        // The pretrace fills the irradiance cache over the whole image, whatever region is
        // rendered, so farm parts share one cache.
        const Camera& camera = prepared->camera;
        auto pixel = [&](double x, double y, RadiosityTicket& ticket) {
            if (std::optional<Ray> ray = camera.generate(x, y)) whitted.li(*ray, &ticket);
        };
        if (!radiosity->pretrace(options.width, options.height, options.threads, options.cancel,
                                 pixel)) {
            // Cancelled before any pixel of the final render: all of it black.
            auto partial = std::make_shared<PartialRender>();
            const Region r = options.region.empty()
                                 ? Region{0, 0, options.width, options.height}
                                 : options.region;
            partial->film.image.width = r.width();
            partial->film.image.height = r.height();
            partial->film.image.rgba.assign(static_cast<size_t>(r.width()) * r.height() * 4, 0.0f);
            partial->tiles_total = static_cast<size_t>((r.width() + kBlockSize - 1) / kBlockSize) *
                                   ((r.height() + kBlockSize - 1) / kBlockSize);
            throw Interrupted(std::move(partial));
        }
        radiosity->start_final(options.width, options.height);
        diag.info("radiosity: " + std::to_string(radiosity->cache_size()) +
                  " samples from the pretrace");
    }
    RadianceFn radiance = [&whitted, radiosity](const Ray& ray, const SampleId& id) {
        if (!radiosity) return whitted.li(ray);
        RadiosityTicket ticket;
        ticket.block = radiosity->final_block(id.block);
        return whitted.li(ray, &ticket);
    };
    result.image = run_tiles(prepared->camera, options, settings, radiance);
    result.render_seconds = seconds_since(t1);
    std::vector<GradientNote> notes;
    prepared->geometry->gradient_notes(&notes);
    report_gradients(notes, scene, diag);
    return result;
}

}  // namespace glint::render
