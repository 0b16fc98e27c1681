#include "render/film/driver.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cfloat>
#include <cmath>
#include <utility>
#include <vector>

#include "core/error.h"
#include "render/focal_blur.h"
#include "render/pov_jitter.h"
#include "render/sampling/sampler.h"

namespace glint::render {
namespace {

// The sampler pair of the camera's lens (depth of field): far past the pairs paths use.
constexpr uint32_t kLensPair = 0x40000000;
// The pair of the shutter time (motion blur): the next one.
constexpr uint32_t kTimePair = kLensPair + 1;

// The film accepts only finite, non-negative values.
float sanitize(double v) {
    if (!(v > 0.0)) return 0.0f;  // negative or NaN
    if (v > FLT_MAX) return FLT_MAX;
    return static_cast<float>(v);
}

struct Tile {
    int x0, y0, x1, y1;  // [x0, x1) x [y0, y1)
};

// The block the calling thread renders (SampleId::block).
thread_local int current_block = -1;

// The pixels to render: the options' region, or the whole image.
Region film_region(const RenderOptions& o) {
    return o.region.empty() ? Region{0, 0, o.width, o.height} : o.region;
}

// The part of a tile inside the region (empty when they do not meet).
Tile clip(const Tile& t, const Region& r) {
    return {std::max(t.x0, r.x0), std::max(t.y0, r.y0), std::min(t.x1, r.x1),
            std::min(t.y1, r.y1)};
}

class TileRenderer {
public:
    // `image` holds the region's pixels only.
    TileRenderer(const Camera& camera, const RenderOptions& options,
                 const DriverSettings& settings, const RadianceFn& radiance, Image* image)
        : camera_(camera), opt_(options), settings_(settings), radiance_(radiance),
          image_(image), region_(film_region(options)) {
        // A mesh_camera's rays come from its faces: POV-Ray gives them no aperture jitter, and
        // glint keeps them as they are.
        if (camera.ir().focal_blur.active() && camera.ir().kind != scene::CameraKind::Mesh)
            blur_ = std::make_shared<const FocalBlur>(camera);
    }

    // False when cancelled before the tile was finished (its pixels are then incomplete).
    bool render(const Tile& t) const {
        const int columns = (opt_.width + kBlockSize - 1) / kBlockSize;
        current_block = (t.y0 / kBlockSize) * columns + t.x0 / kBlockSize;
        switch (opt_.aa) {
            case AaMode::None: return none(t);
            case AaMode::Grid: return grid(t);
            case AaMode::Adaptive: return adaptive(t);
            case AaMode::Adaptive2: return adaptive2(t);
        }
        return false;
    }

private:
    bool cancelled() const {
        return opt_.cancel && opt_.cancel->load(std::memory_order_relaxed);
    }

    Color sample(double x, double y, int px, int py, uint32_t index) const {
        if (blur_) {
            return blur_->pixel(x, y, [&](const Ray& ray) {
                return radiance_(ray, SampleId{px, py, index, current_block});
            });
        }
        const int rays = camera_.rays_per_pixel();
        if (rays == 1) {
            std::optional<Ray> ray = camera_.generate(x, y);
            if (!ray) return Color(0, 0, 0);
            return radiance_(*ray, SampleId{px, py, index, current_block});
        }
        // A mesh_camera's rays: the mean of those that have a face (TracePixel::operator()).
        Color sum;
        int traced = 0;
        for (int k = 0; k < rays; ++k) {
            std::optional<Ray> ray = camera_.generate(x, y, k);
            if (!ray) continue;
            sum += radiance_(*ray, SampleId{px, py, index, current_block});
            ++traced;
        }
        return traced > 0 ? sum * (1.0 / traced) : Color(0, 0, 0);
    }
    Color sample(int px, int py) const { return sample(px, py, px, py, 0); }

    // Pixel (x, y) of the whole image, which must lie in the region.
    void store(int x, int y, const Color& c) const {
        float* p = image_->pixel(x - region_.x0, y - region_.y0);
        p[0] = sanitize(c.r);
        p[1] = sanitize(c.g);
        p[2] = sanitize(c.b);
        p[3] = 1.0f;
    }

    bool none(const Tile& tile) const {
        const Tile t = clip(tile, region_);
        for (int y = t.y0; y < t.y1; ++y) {
            if (cancelled()) return false;
            for (int x = t.x0; x < t.x1; ++x) store(x, y, sample(x, y));
        }
        return true;
    }

    bool grid(const Tile& tile) const {
        const Tile t = clip(tile, region_);
        int n = std::max(1, opt_.grid_n);
        for (int y = t.y0; y < t.y1; ++y) {
            for (int x = t.x0; x < t.x1; ++x) {
                if (cancelled()) return false;  // up to 64 x 64 samples a pixel
                Color sum;
                for (int j = 0; j < n; ++j)
                    for (int i = 0; i < n; ++i)
                        sum += sample(x + (i + 0.5) / n - 0.5, y + (j + 0.5) / n - 0.5, x, y,
                                      static_cast<uint32_t>(j * n + i));
                store(x, y, sum / static_cast<double>(n * n));
            }
        }
        return true;
    }

    // Color as compared by adaptive AA: linear, then encoded with antialias_gamma 2.5.
    Color aa_encode(const Color& c) const {
        auto enc = [&](double v) {
            if (!(v > 0.0)) return 0.0;
            if (settings_.working_gamma != 1.0) v = std::pow(v, settings_.working_gamma);
            return std::pow(v, 1.0 / 2.5);
        };
        return Color(enc(c.r), enc(c.g), enc(c.b));
    }

    bool differs(const Color& a, const Color& b) const {
        Color ea = aa_encode(a), eb = aa_encode(b);
        double d = std::fabs(ea.r - eb.r) + std::fabs(ea.g - eb.g) + std::fabs(ea.b - eb.b);
        return d >= opt_.aa_threshold;
    }

    // Sample `index` of pixel (px, py) at raster position (x, y), moved by POV-Ray's jitter
    // of that position times `scale` (no move at scale 0).
    Color jittered(double x, double y, double scale, int px, int py, uint32_t index) const {
        if (scale > 0.0) {
            double rx, ry;
            pov_jitter2d(x, y, &rx, &ry);
            x += rx * scale;
            y += ry * scale;
        }
        return sample(x, y, px, py, index);
    }

    // SupersampleOnePixel: aa_depth x aa_depth grid plus the centre sample, averaged. The loop
    // is POV-Ray's, offsets accumulated as it adds them, because the jitter hashes the exact
    // position (an offset a rounding away lands in another hash cell).
    void supersample(int x, int y, Color* col) const {
        const int depth = std::max(1, opt_.aa_depth);
        const double step = 1.0 / depth;
        const double range = 0.5 - step * 0.5;
        const double scale = opt_.aa_jitter / depth;
        constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON
        uint32_t index = 1;
        for (double yy = -range; yy <= range + kEpsilon; yy += step)
            for (double xx = -range; xx <= range + kEpsilon; xx += step)
                *col += jittered(x + xx, y + yy, scale, x, y, index++);
        *col = *col / static_cast<double>(depth * depth + 1);
    }

    // POV-Ray's sampling method 1 (tracetask.cpp NonAdaptiveSupersamplingM1): each pixel is
    // compared with its left and top neighbours inside the block (plus a border row and
    // column traced but never supersampled); differing pixels are supersampled once.
    bool adaptive(const Tile& t) const {
        int w = t.x1 - t.x0 + 1, h = t.y1 - t.y0 + 1;
        std::vector<Color> px(static_cast<size_t>(w) * h);
        std::vector<char> done(static_cast<size_t>(w) * h, 0);
        auto at = [&](int x, int y) -> size_t { return (y - t.y0 + 1) * w + (x - t.x0 + 1); };
        for (int x = t.x0; x < t.x1; ++x) {
            px[at(x, t.y0 - 1)] = sample(x, t.y0 - 1);
            done[at(x, t.y0 - 1)] = 1;
        }
        for (int y = t.y0; y < t.y1; ++y) {
            if (cancelled()) return false;
            px[at(t.x0 - 1, y)] = sample(t.x0 - 1, y);
            done[at(t.x0 - 1, y)] = 1;
            for (int x = t.x0; x < t.x1; ++x) {
                px[at(x, y)] = sample(x, y);
                bool sample_left = !done[at(x - 1, y)];
                bool sample_top = !done[at(x, y - 1)];
                bool left_diff = differs(px[at(x - 1, y)], px[at(x, y)]);
                bool top_diff = differs(px[at(x, y - 1)], px[at(x, y)]);
                sample_left = sample_left && left_diff;
                sample_top = sample_top && top_diff;
                bool sample_cur = left_diff || top_diff;
                if (sample_left) supersample(x - 1, y, &px[at(x - 1, y)]);
                if (sample_top) supersample(x, y - 1, &px[at(x, y - 1)]);
                if (sample_cur) supersample(x, y, &px[at(x, y)]);
                if (sample_left) done[at(x - 1, y)] = 1;
                if (sample_top) done[at(x, y - 1)] = 1;
                if (sample_cur) done[at(x, y)] = 1;
            }
        }
        // The whole block was traced (its pixels depend on their neighbours in it); the
        // region keeps its own.
        const Tile kept = clip(t, region_);
        for (int y = kept.y0; y < kept.y1; ++y)
            for (int x = kept.x0; x < kept.x1; ++x) store(x, y, px[at(x, y)]);
        return true;
    }

    // The samples of one pixel under sampling method 2: a (2^depth + 1)^2 grid over the pixel,
    // corner (0, 0) at its upper-left corner, filled as subdivision asks.
    struct SubdivisionGrid {
        int size;
        std::vector<Color> color;
        std::vector<char> taken;
        explicit SubdivisionGrid(int n)
            : size(n), color(static_cast<size_t>(n) * n), taken(static_cast<size_t>(n) * n) {}
        size_t at(int bx, int by) const { return static_cast<size_t>(by) * size + bx; }
        void set(int bx, int by, const Color& c) {
            color[at(bx, by)] = c;
            taken[at(bx, by)] = 1;
        }
    };

    // SubdivideOnePixel: the square of side 2d around (x, y), its corners at grid cells
    // (bx, by) .. (bx + step, by + step), is split in four (its edge midpoints and centre
    // traced, jittered) while `level` allows and any two corners differ; the result is the
    // mean of the quarters, or of the corners.
    void subdivide(double x, double y, double d, int bx, int by, int step, SubdivisionGrid& g,
                   Color* result, int level, int px, int py) const {
        const Color c00 = g.color[g.at(bx, by)], c02 = g.color[g.at(bx, by + step)];
        const Color c20 = g.color[g.at(bx + step, by)];
        const Color c22 = g.color[g.at(bx + step, by + step)];
        const bool split = level > 0 && (differs(c00, c02) || differs(c00, c20) ||
                                         differs(c00, c22) || differs(c02, c20) ||
                                         differs(c02, c22) || differs(c20, c22));
        if (!split) {
            *result = (c00 + c02 + c20 + c22) / 4.0;
            return;
        }
        const int half = step / 2;
        const double scale = opt_.aa_jitter / ((1 << std::max(1, opt_.aa_depth)) + 1);
        auto take = [&](int cx, int cy, double sx, double sy) {
            if (g.taken[g.at(cx, cy)]) return;
            g.set(cx, cy, jittered(sx, sy, scale, px, py, static_cast<uint32_t>(1 + g.at(cx, cy))));
        };
        take(bx, by + half, x - d, y);
        take(bx + half, by, x, y - d);
        take(bx + step, by + half, x + d, y);
        take(bx + half, by + step, x, y + d);
        take(bx + half, by + half, x, y);
        const double d2 = d * 0.5;
        Color r00, r01, r10, r11;
        subdivide(x - d2, y - d2, d2, bx, by, half, g, &r00, level - 1, px, py);
        subdivide(x - d2, y + d2, d2, bx, by + half, half, g, &r01, level - 1, px, py);
        subdivide(x + d2, y - d2, d2, bx + half, by, half, g, &r10, level - 1, px, py);
        subdivide(x + d2, y + d2, d2, bx + half, by + half, half, g, &r11, level - 1, px, py);
        *result = (r00 + r01 + r10 + r11) / 4.0;
    }

    // POV-Ray's sampling method 2 (tracetask.cpp AdaptiveSupersamplingM2): the pixels'
    // corners are traced unjittered, then each pixel is subdivided from its four corners
    // alone, so a pixel depends on no neighbour and the region needs no whole block.
    bool adaptive2(const Tile& tile) const {
        const Tile t = clip(tile, region_);
        const int depth = std::max(1, opt_.aa_depth);
        const int w = t.x1 - t.x0 + 1;
        std::vector<Color> corner(static_cast<size_t>(w) * (t.y1 - t.y0 + 1));
        auto at = [&](int x, int y) -> size_t {
            return static_cast<size_t>(y - t.y0) * w + (x - t.x0);
        };
        for (int y = t.y0; y <= t.y1; ++y) {
            if (cancelled()) return false;
            for (int x = t.x0; x <= t.x1; ++x) corner[at(x, y)] = sample(x - 0.5, y - 0.5, x, y, 0);
        }
        SubdivisionGrid g((1 << depth) + 1);
        const int n = g.size - 1;
        for (int y = t.y0; y < t.y1; ++y) {
            if (cancelled()) return false;
            for (int x = t.x0; x < t.x1; ++x) {
                std::fill(g.taken.begin(), g.taken.end(), 0);
                g.set(0, 0, corner[at(x, y)]);
                g.set(0, n, corner[at(x, y + 1)]);
                g.set(n, 0, corner[at(x + 1, y)]);
                g.set(n, n, corner[at(x + 1, y + 1)]);
                Color c;
                subdivide(x, y, 0.5, 0, 0, n, g, &c, depth - 1, x, y);
                store(x, y, c);
            }
        }
        return true;
    }

    const Camera& camera_;
    const RenderOptions& opt_;
    const DriverSettings& settings_;
    const RadianceFn& radiance_;
    Image* image_;
    Region region_;
    std::shared_ptr<const FocalBlur> blur_;  // POV-Ray focal blur, when the camera has it
};

// The blocks of the whole width x height image that meet the region, in image order.
std::vector<Tile> make_tiles(int width, int height, const Region& region) {
    std::vector<Tile> tiles;
    for (int y = 0; y < height; y += kBlockSize)
        for (int x = 0; x < width; x += kBlockSize) {
            const Tile t{x, y, std::min(x + kBlockSize, width), std::min(y + kBlockSize, height)};
            const Tile c = clip(t, region);
            if (c.x0 < c.x1 && c.y0 < c.y1) tiles.push_back(t);
        }
    return tiles;
}

// Sets every region pixel of the tiles not marked done to transparent black (RGBA 0).
void clear_unfinished(Image* image, const std::vector<Tile>& tiles,
                      const std::vector<char>& done, const Region& region) {
    if (image->rgba.empty()) return;
    for (size_t i = 0; i < tiles.size(); ++i) {
        if (done[i]) continue;
        const Tile t = clip(tiles[i], region);
        for (int y = t.y0; y < t.y1; ++y)
            for (int x = t.x0; x < t.x1; ++x)
                std::fill_n(image->pixel(x - region.x0, y - region.y0), 4, 0.0f);
    }
}

void check_region(const RenderOptions& o) {
    if (o.width <= 0 || o.height <= 0) throw Error(ErrorKind::Usage, {}, "image size must be positive");
    const Region& r = o.region;
    if (r.empty() && (r.x0 | r.y0 | r.x1 | r.y1) == 0) return;
    if (r.empty() || r.x0 < 0 || r.y0 < 0 || r.x1 > o.width || r.y1 > o.height)
        throw Error(ErrorKind::Usage, {},
                    "region " + std::to_string(r.x0) + "," + std::to_string(r.y0) + "," +
                        std::to_string(r.x1) + "," + std::to_string(r.y1) +
                        " is not a non-empty rectangle inside the " + std::to_string(o.width) +
                        "x" + std::to_string(o.height) + " image");
}

}  // namespace

Image run_tiles(const Camera& camera, const RenderOptions& options,
                const DriverSettings& settings, const RadianceFn& radiance) {
    check_region(options);
    const Region region = film_region(options);
    Image image;
    image.width = region.width();
    image.height = region.height();
    image.rgba.assign(static_cast<size_t>(image.width) * image.height * 4, 0.0f);

    const std::vector<Tile> tiles = make_tiles(options.width, options.height, region);
    std::vector<char> tile_done(tiles.size(), 0);  // each written by the one thread of its tile

    TileRenderer renderer(camera, options, settings, radiance, &image);
    std::atomic<size_t> finished{0};
    std::atomic<bool> cancelled{false};
    auto body = [&](const tbb::blocked_range<size_t>& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
            if (!renderer.render(tiles[i])) {
                cancelled = true;
                return;
            }
            tile_done[i] = 1;
            size_t n = ++finished;
            if (options.progress) options.progress(static_cast<double>(n) / tiles.size());
        }
    };
    int threads = options.threads > 0 ? options.threads : tbb::task_arena::automatic;
    tbb::task_arena arena(threads);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1), body,
                          tbb::simple_partitioner());
    });
    if (cancelled || (options.cancel && options.cancel->load())) {
        auto partial = std::make_shared<PartialRender>();
        clear_unfinished(&image, tiles, tile_done, region);
        partial->film.image = std::move(image);
        partial->tiles_total = tiles.size();
        partial->tiles_done = static_cast<size_t>(std::count(tile_done.begin(), tile_done.end(), 1));
        throw Interrupted(std::move(partial));
    }
    return image;
}

namespace {

// A finite film value of either sign (normals): NaN becomes 0, infinities the largest float.
float finite_signed(double v) {
    if (std::isnan(v)) return 0.0f;
    return static_cast<float>(std::clamp(v, -static_cast<double>(FLT_MAX),
                                         static_cast<double>(FLT_MAX)));
}

Image blank_image(int width, int height) {
    Image image;
    image.width = width;
    image.height = height;
    image.rgba.assign(static_cast<size_t>(width) * height * 4, 0.0f);
    for (size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 1.0f;
    return image;
}

// Per-pixel running sums of the optional outputs, in sample order.
struct PixelAccumulators {
    std::vector<double> aov;      // 7 per pixel: albedo rgb, normal xyz, depth
    std::vector<double> mean;     // 3 per pixel: Welford's running mean
    std::vector<double> m2;       // 3 per pixel: Welford's sum of squared deviations
    std::vector<double> transparent;  // 1 per pixel: FirstHit::transparent (options.alpha)
};

}  // namespace

std::optional<Ray> path_camera_ray(const Camera& camera, const PixelFilter& filter,
                                   const Shutter* shutter, const PixelSampler& ps, int x, int y,
                                   uint32_t index) {
    const Sample2 j = ps.get2(0);
    const double fx = x + filter.offset(j.u), fy = y + filter.offset(j.v);
    std::optional<Ray> ray;
    if (camera.rays_per_pixel() > 1) {
        // A mesh_camera's rays in turn, sample by sample.
        return camera.generate(fx, fy, static_cast<int>(index % camera.rays_per_pixel()));
    }
    if (camera.has_lens()) {
        // A pair no bounce uses: the aperture's point.
        const Sample2 l = ps.get2(kLensPair);
        ray = camera.generate(fx, fy, l.u, l.v);
    } else {
        ray = camera.generate(fx, fy);
    }
    if (ray && shutter && shutter->active())
        shutter->expose(Shutter::time(ps.get2(kTimePair).u), &*ray);
    return ray;
}

int run_path_tiles(const Camera& camera, const RenderOptions& options,
                   const PathRadianceFn& radiance, PathFilm* film, const Shutter* shutter) {
    check_region(options);
    if (shutter && !shutter->active()) shutter = nullptr;
    const Region region = film_region(options);
    const int fw = region.width(), fh = region.height();  // the film: the region
    const auto start = std::chrono::steady_clock::now();
    const size_t pixels = static_cast<size_t>(fw) * fh;
    std::vector<double> sum(pixels * 3, 0.0);
    PixelAccumulators extra;
    if (options.aovs) extra.aov.assign(pixels * 7, 0.0);
    if (options.alpha) extra.transparent.assign(pixels, 0.0);
    if (options.variance) {
        extra.mean.assign(pixels * 3, 0.0);
        extra.m2.assign(pixels * 3, 0.0);
    }
    const std::vector<Tile> tiles = make_tiles(options.width, options.height, region);
    const PixelFilter filter(options.pixel_filter, options.filter_width);
    const int total = std::max(1, options.spp);
    int done = 0;
    // Adaptive sampling (Cycles' Noise Threshold, Integrator::get_adaptive_sampling and
    // film_adaptive_sampling_convergence_check): the threshold (automatic: 1 / spp, at least
    // 0.001) and the minimum samples (automatic: 16 / threshold^0.3, at least 4) as Cycles
    // derives them, the threshold then times 5 as Cycles scales it. Each pixel keeps, beside
    // its sum, twice the sum of its even samples; every 16 samples past the minimum, a pixel
    // whose two estimates differ by less than the threshold (relative to the square root of
    // its brightness) stops. The decision is the pixel's own (Cycles also widens the pixels
    // still sampling by one in x and y: left out, so that a region renders each pixel as the
    // whole image does), made between passes, so the image does not depend on the threads.
    constexpr int kAdaptiveStep = 16;
    const bool adaptive = options.adaptive;
    double threshold = 0;
    int min_samples = 0;
    std::vector<int> taken;      // adaptive: samples per pixel
    std::vector<double> half;    // adaptive: 2 x the sum of the even samples, per channel
    std::vector<char> sampling;  // adaptive: the pixel still takes samples
    if (adaptive) {
        float t = options.adaptive_threshold > 0 ? static_cast<float>(options.adaptive_threshold)
                                                 : std::max(0.001f, 1.0f / total);
        min_samples = options.adaptive_min_samples > 0
                          ? std::max(4, options.adaptive_min_samples)
                          : std::max(4, static_cast<int>(std::ceil(16.0f / std::pow(t, 0.3f))));
        threshold = t * 5.0f;
        taken.assign(pixels, 0);
        half.assign(pixels * 3, 0.0);
        sampling.assign(pixels, 1);
    }
    std::atomic<bool> cancelled{false};
    auto cancel_requested = [&options] {
        return options.cancel && options.cancel->load(std::memory_order_relaxed);
    };
    // The outputs at n samples per pixel from the sums; after every finished pass, so an
    // interruption finds the last pass's film ready (and the last one is the result).
    auto resolve = [&](int n, PathFilm* out) {
        out->image = blank_image(fw, fh);
        // Adaptive sampling: each pixel over its own samples.
        auto inv_of = [&](size_t i) { return 1.0 / (adaptive ? std::max(1, taken[i]) : n); };
        for (size_t i = 0; i < pixels; ++i) {
            const double inv = inv_of(i);
            for (int c = 0; c < 3; ++c) out->image.rgba[i * 4 + c] = sanitize(sum[i * 3 + c] * inv);
        }
        // Cycles' film_transparency_to_alpha: clamped, since roulette can push it past 0..1.
        if (!extra.transparent.empty())
            for (size_t i = 0; i < pixels; ++i)
                out->image.rgba[i * 4 + 3] = static_cast<float>(
                    std::clamp(1.0 - extra.transparent[i] * inv_of(i), 0.0, 1.0));
        if (!extra.aov.empty()) {
            out->albedo = blank_image(fw, fh);
            out->normal = blank_image(fw, fh);
            out->depth = blank_image(fw, fh);
            for (size_t i = 0; i < pixels; ++i) {
                const double* a = &extra.aov[i * 7];
                const double inv = inv_of(i);
                for (int c = 0; c < 3; ++c) {
                    out->albedo.rgba[i * 4 + c] = sanitize(a[c] * inv);
                    out->normal.rgba[i * 4 + c] = finite_signed(a[3 + c] * inv);
                    out->depth.rgba[i * 4 + c] = sanitize(a[6] * inv);
                }
            }
        }
        if (!extra.mean.empty()) {
            out->variance = blank_image(fw, fh);
            for (size_t i = 0; i < pixels; ++i) {
                const double k = adaptive ? taken[i] : n;
                if (k < 2) continue;
                const double scale = 1.0 / (k * (k - 1));
                for (int c = 0; c < 3; ++c)
                    out->variance.rgba[i * 4 + c] = sanitize(extra.m2[i * 3 + c] * scale);
            }
        }
    };
    int threads = options.threads > 0 ? options.threads : tbb::task_arena::automatic;
    tbb::task_arena arena(threads);
    while (done < total) {
        int pass = std::min(total - done, std::max(1, done));
        if (adaptive && done >= kAdaptiveStep) pass = std::min(pass, kAdaptiveStep);
        const int s0 = done, s1 = done + pass;
        std::atomic<size_t> finished{0};
        std::vector<char> tile_done(tiles.size(), 0);
        auto body = [&](const tbb::blocked_range<size_t>& range) {
            for (size_t i = range.begin(); i != range.end(); ++i) {
                const Tile t = clip(tiles[i], region);
                for (int y = t.y0; y < t.y1; ++y) {
                    for (int x = t.x0; x < t.x1; ++x) {
                        const size_t p =
                            static_cast<size_t>(y - region.y0) * fw + (x - region.x0);
                        if (adaptive && !sampling[p]) continue;
                        double* acc = &sum[p * 3];
                        for (int s = s0; s < s1; ++s) {
                            if (cancel_requested()) {
                                cancelled = true;
                                return;
                            }
                            const uint32_t index = static_cast<uint32_t>(s);
                            const PixelSampler ps(x, y, index, options.seed);
                            const std::optional<Ray> ray =
                                path_camera_ray(camera, filter, shutter, ps, x, y, index);
                            float value[3] = {0, 0, 0};
                            FirstHit first;
                            if (ray) {
                                const bool want = options.aovs || options.alpha;
                                const Color c = radiance(*ray, SampleId{x, y, index},
                                                         want ? &first : nullptr);
                                value[0] = sanitize(c.r);
                                value[1] = sanitize(c.g);
                                value[2] = sanitize(c.b);
                                acc[0] += value[0];
                                acc[1] += value[1];
                                acc[2] += value[2];
                                if (adaptive && s % 2 == 0)
                                    for (int c = 0; c < 3; ++c) half[p * 3 + c] += 2.0 * value[c];
                            }
                            if (adaptive) ++taken[p];
                            if (!extra.transparent.empty() && std::isfinite(first.transparent))
                                extra.transparent[p] += first.transparent;
                            if (!extra.aov.empty() && first.hit) {
                                double* a = &extra.aov[p * 7];
                                a[0] += sanitize(first.albedo.r);
                                a[1] += sanitize(first.albedo.g);
                                a[2] += sanitize(first.albedo.b);
                                a[3] += finite_signed(first.normal.x);
                                a[4] += finite_signed(first.normal.y);
                                a[5] += finite_signed(first.normal.z);
                                a[6] += sanitize(first.depth);
                            }
                            if (!extra.mean.empty()) {
                                // Welford (1962): stable where sum-of-squares cancels. A
                                // sample without a camera ray counts as 0, as in the mean.
                                const double k = s + 1.0;
                                for (int c = 0; c < 3; ++c) {
                                    double& m = extra.mean[p * 3 + c];
                                    const double d = value[c] - m;
                                    m += d / k;
                                    extra.m2[p * 3 + c] += d * (value[c] - m);
                                }
                            }
                        }
                    }
                }
                tile_done[i] = 1;
                const size_t n = ++finished;
                if (options.progress)
                    options.progress((s0 + static_cast<double>(pass) * n / tiles.size()) / total);
            }
        };
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1), body,
                              tbb::simple_partitioner());
        });
        if (cancelled || (options.cancel && options.cancel->load())) {
            auto partial = std::make_shared<PartialRender>();
            partial->spp_requested = total;
            partial->tiles_total = tiles.size();
            if (done > 0) {
                partial->film = std::move(*film);  // the last finished pass
                partial->samples_per_pixel = done;
                partial->tiles_done = tiles.size();
            } else {
                // The first pass's finished tiles hold exactly their one sample.
                resolve(1, &partial->film);
                for (Image* image : {&partial->film.image, &partial->film.albedo,
                                     &partial->film.normal, &partial->film.depth,
                                     &partial->film.variance})
                    clear_unfinished(image, tiles, tile_done, region);
                partial->tiles_done =
                    static_cast<size_t>(std::count(tile_done.begin(), tile_done.end(), 1));
            }
            throw Interrupted(std::move(partial));
        }
        done = s1;
        bool any_sampling = true;
        if (adaptive && done >= min_samples && done % kAdaptiveStep == 0) {
            any_sampling = false;
            for (size_t p = 0; p < pixels; ++p) {
                if (!sampling[p]) continue;
                const double* I = &sum[p * 3];
                const double* A = &half[p * 3];
                const double inv = 1.0 / std::max(1, taken[p]);
                const double difference =
                    (std::fabs(I[0] - A[0]) + std::fabs(I[1] - A[1]) + std::fabs(I[2] - A[2])) *
                    inv;
                const double normalize = std::sqrt((I[0] + I[1] + I[2]) * inv);
                if (difference / (0.0001 + normalize) < threshold) sampling[p] = 0;
                any_sampling = any_sampling || sampling[p];
            }
        }
        resolve(done, film);
        if (!any_sampling) break;  // every pixel converged
        if (options.time_limit > 0 &&
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >=
                options.time_limit)
            break;
    }
    return done;
}

int run_path_tiles(const Camera& camera, const RenderOptions& options, const RadianceFn& radiance,
                   Image* image) {
    PathRadianceFn plain = [&radiance](const Ray& ray, const SampleId& id, FirstHit*) {
        return radiance(ray, id);
    };
    RenderOptions o = options;
    o.aovs = false;
    o.variance = false;
    o.alpha = false;  // a plain radiance function says nothing of transparency
    PathFilm film;
    const int done = run_path_tiles(camera, o, plain, &film);
    *image = std::move(film.image);
    return done;
}

}  // namespace glint::render
