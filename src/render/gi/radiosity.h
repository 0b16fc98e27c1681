// POV-Ray 3.7's radiosity (backend/lighting/radiosity.cpp, backend/render/radiositytask.cpp,
// the reference manual's "Radiosity" section): the diffuse interreflection that replaces
// ambient, gathered by shooting `count` cosine-distributed rays from a point, cached in an
// irradiance cache (radiosity_cache.h) and reused nearby by Ward's error bound. Pretrace
// passes at `pretrace_start` .. `pretrace_end` of the image size fill the cache coarse to
// fine before the final render, which reuses what it finds and gathers where it finds none.
//
// Determinism: POV-Ray reuses samples of the same pass taken by other threads, so its image
// depends on the thread count. Here every pass (pretrace or final) reads the cache as the
// previous passes left it plus the samples of its own 32-pixel block, and a pass's samples
// join the cache in block order when it ends: the image is the same whatever the thread count
// (and whichever region a farm part renders).
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <vector>

#include "render/gi/radiosity_cache.h"
#include "render/ray.h"
#include "scene/scene.h"

namespace glint::render {

// One image block's view of the cache during a pass: its own new samples, where its
// sample directions have got to, and the counts the adaptive pretrace decides by.
struct RadiosityBlock {
    int pass = 0;  // 1, 2, ... for pretrace passes; 0 for the final render
    RadiosityCache local;
    std::vector<uint32_t> next_direction;  // per recursion depth
    long queries = 0;                      // top-level lookups since the counts were reset
    double reuse = 0;                      // their summed reuse (times 4, as POV-Ray counts)
};

// POV-Ray's TraceTicket fields radiosity reads and writes along one camera sample.
struct RadiosityTicket {
    RadiosityBlock* block = nullptr;
    int depth = 0;           // radiosity recursion depth of the ray being traced
    double quality = 1;      // lowered by lookups that found fewer samples than they wanted
    double importance_queried = -1;  // >= 0: the sample ray's share, checked at its hit
    double importance_found = 1;
    bool pretrace = false;   // a pretrace camera ray (and its reflections and refractions)
};

// Where the indirect light is wanted: the hit point with its error bound and geometric
// normal (to start rays off the surface), the raw normal facing the viewer and the layer's
// perturbed normal.
struct RadiosityPoint {
    Vec3 p, p_error, ng, raw_n, layer_n;
};

// The classic integrator's side: traces one radiosity sample ray (a new ray, with the ticket
// at the sample's depth + 1) and returns its colour and hit distance (infinity on a miss).
// `trace_level` is the trace level the ray starts at (POV-Ray restarts it per depth).
using RadiosityTraceFn = std::function<Color(const Ray& ray, double weight, int trace_level,
                                             RadiosityTicket& ticket, double* depth)>;

class Radiosity {
public:
    Radiosity(const scene::Radiosity& settings, const Vec3& camera);

    const scene::Radiosity& settings() const { return s_; }
    // CheckRadiosityTraceLevel: whether a hit at the ticket's depth gets radiosity.
    bool recurses(const RadiosityTicket& t) const { return t.depth < s_.recursion_limit; }

    // ComputeAmbient: the indirect irradiance at `at` (brightness and gray_threshold
    // applied), reusing cached samples or gathering a new one. `weight` is the ray's weight
    // times the most this term can add (it widens the error bound under 0.25).
    Color ambient(const RadiosityPoint& at, double weight, RadiosityTicket& ticket,
                  const RadiosityTraceFn& trace) const;

    // The pretrace over the whole width x height image: `pixel` traces the camera ray at
    // image position (x, y) with the ticket given. Runs on `threads` threads (0: all);
    // returns false when `cancel` was set.
    using PixelFn = std::function<void(double x, double y, RadiosityTicket& ticket)>;
    bool pretrace(int width, int height, int threads, const std::atomic<bool>* cancel,
                  const PixelFn& pixel);
    // The final render's block for the driver's block `index` (of a width x height image,
    // 32-pixel blocks in rows); each block is rendered by one thread at a time.
    RadiosityBlock* final_block(int index) const;
    void start_final(int width, int height);

    size_t cache_size() const { return cache_.size(); }

private:
    // One image block's pretrace (RadiosityTask::Run) for pass `pass` (0-based).
    struct PretraceBlock;
    void pretrace_block(PretraceBlock& b, int pass, int steps, double start, double end,
                        const PixelFn& pixel) const;
    // POV-Ray's RadiosityRecursionSettings, per depth.
    struct Depth {
        int rays;
        int reuse_count;
        double error_bound_factor, min_reuse, max_reuse;
        int trace_level;
        double weight;
        double address_factor;  // octree filing radius per harmonic mean distance
    };
    // The cached samples usable at `p` for the ticket's depth and block.
    RadiosityReuse find(const Vec3& p, const Vec3& n, double error_bound,
                        const RadiosityTicket& ticket) const;
    double gather_light(const RadiosityPoint& at, const Vec3& normal, RadiosityTicket& ticket,
                        const RadiosityTraceFn& trace, Color* illuminance) const;

    scene::Radiosity s_;
    Vec3 camera_;
    std::vector<Depth> depths_;
    std::vector<Vec3> directions_;  // the cosine-weighted pool, +Y up
    RadiosityCache cache_;          // changes only between passes
    mutable std::vector<std::unique_ptr<RadiosityBlock>> final_blocks_;
};

}  // namespace glint::render
