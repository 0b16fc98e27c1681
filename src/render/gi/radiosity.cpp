#include "render/gi/radiosity.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <deque>

#include "core/float.h"
#include "render/film/film.h"

namespace glint::render {
namespace {

// radiosity.cpp: WEIGHT_ERROR_BOUND_OFFSET and RAD_EPSILON (the "straight up" tolerance).
constexpr double kWeightErrorBoundOffset = 0.25;
constexpr double kUpEpsilon = 0.001;
constexpr double kEpsilon = 1.0e-10;  // POV-Ray's EPSILON

// POV-Ray's greyscale weights.
double greyscale(const Color& c) { return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b; }

// The radical inverse of i in `base`: the Halton sequence from its second element, as
// POV-Ray's HaltonGenerator numbers it.
double halton(uint32_t i, uint32_t base) {
    double h = 0, q = 1.0 / base;
    for (uint32_t k = i + 1; k > 0; k /= base, q /= base) h += (k % base) * q;
    return h;
}

// A reproducible number in [-1, 1] for the pretrace jitter.
double jitter_number(uint64_t a, uint64_t b, uint64_t c) {
    uint64_t h = a * 0x9E3779B97F4A7C15ull ^ (b + 0x632BE59BD9B4E019ull) * 0xBF58476D1CE4E5B9ull ^
                 (c + 0x8CB92BA72F3D8DD7ull) * 0x94D049BB133111EBull;
    h ^= h >> 31;
    h *= 0xD6E8FEB86659FD93ull;
    h ^= h >> 32;
    return static_cast<double>(h >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

bool similar(const Vec3& a, const Vec3& b) {
    return std::fabs(a.x - b.x) < kEpsilon && std::fabs(a.y - b.y) < kEpsilon &&
           std::fabs(a.z - b.z) < kEpsilon;
}

// SampleDirectionGenerator: the pool's directions turned so +Y becomes the normal, skipping
// those below the raw surface; tries a bounded number when following a perturbed normal.
class Directions {
public:
    Directions(const std::vector<Vec3>& pool, uint32_t* next) : pool_(pool), next_(next) {}

    void start(int* count, const Vec3& raw_n, const Vec3& layer_n, bool use_raw) {
        const size_t n = pool_.size();
        *count = static_cast<int>(std::min(static_cast<size_t>(*count), n));
        remaining_ = use_raw ? n : std::min(static_cast<size_t>(*count) * 5, n);
        raw_mode_ = use_raw;
        raw_ = raw_n;
        y_ = use_raw ? raw_n : layer_n;
        const Vec3 off = std::fabs(y_.z) > 0.9 ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
        x_ = normalize(cross(y_, off));
        z_ = normalize(cross(x_, y_));
    }

    bool next(Vec3* dir) {
        double ok = -1;
        while (remaining_ > 0) {
            const Vec3& v = pool_[*next_ % pool_.size()];
            *next_ = static_cast<uint32_t>((*next_ + 1) % pool_.size());
            --remaining_;
            if (y_.y > 1.0 - kUpEpsilon) *dir = v;
            else if (y_.y < -1.0 + kUpEpsilon) *dir = -v;
            else *dir = x_ * v.x + y_ * v.y + z_ * v.z;
            ok = raw_mode_ ? 1.0 : dot(*dir, raw_);
            if (ok > 0) return true;
        }
        return false;
    }

private:
    const std::vector<Vec3>& pool_;
    uint32_t* next_;
    size_t remaining_ = 0;
    bool raw_mode_ = false;
    Vec3 raw_, x_, y_, z_;
};

}  // namespace

Radiosity::Radiosity(const scene::Radiosity& settings, const Vec3& camera)
    : s_(settings), camera_(camera) {
    // GetRecursionSettings.
    for (int d = 0; d < s_.recursion_limit; ++d) {
        Depth r;
        const double grow = std::pow(2.0, d);
        r.rays = std::max(5, static_cast<int>(s_.count * std::pow(0.5, d)));
        r.reuse_count = d == 0 ? s_.nearest_count : d == 1 ? std::min(2, s_.nearest_count) : 1;
        r.error_bound_factor = grow;
        r.min_reuse = s_.minimum_reuse * grow;
        r.max_reuse = s_.maximum_reuse * grow;
        r.trace_level = static_cast<int>(1.5 * (d + 1));
        r.weight = std::pow(0.5 * s_.brightness, d + 1);
        const double overfill = d == 0 ? 1.0 : 8.0;
        r.address_factor = s_.error_bound * r.error_bound_factor / overfill;
        depths_.push_back(r);
    }
    // The direction pool: cosine-distributed directions around +Y from the 2D Halton
    // sequence in bases 2 and 3 (POV-Ray's GetSubRandomCosWeightedDirectionGenerator for
    // pools of 1600 and more; its fixed table for smaller pools is not reproduced).
    const int pool = std::max(s_.direction_pool, s_.count);
    directions_.reserve(pool);
    for (int i = 0; i < pool; ++i) {
        const double r = std::sqrt(halton(i, 2));
        const double theta = 2 * kPi * halton(i, 3);
        const double x = r * std::cos(theta), z = r * std::sin(theta);
        directions_.emplace_back(x, std::sqrt(std::max(0.0, 1 - x * x - z * z)), z);
    }
}

RadiosityReuse Radiosity::find(const Vec3& p, const Vec3& n, double error_bound,
                               const RadiosityTicket& ticket) const {
    RadiosityReuse r;
    const bool smooth = ticket.block->pass == 0 && ticket.depth == 0;
    cache_.gather(p, n, ticket.depth, error_bound, smooth, &r);
    ticket.block->local.gather(p, n, ticket.depth, error_bound, smooth, &r);
    return r;
}

Color Radiosity::ambient(const RadiosityPoint& at, double weight, RadiosityTicket& ticket,
                         const RadiosityTraceFn& trace) const {
    const Depth& d = depths_[static_cast<size_t>(ticket.depth)];
    RadiosityBlock& block = *ticket.block;
    const bool final_trace = block.pass == 0;
    double error_bound = s_.error_bound * (final_trace ? 1.0 : s_.low_error_factor);
    if (weight < kWeightErrorBoundOffset) error_bound += kWeightErrorBoundOffset - weight;
    const Vec3 normal = s_.normal ? at.layer_n : at.raw_n;
    RadiosityReuse found = find(at.p, normal, error_bound * d.error_bound_factor, ticket);
    double reuse = found.weight;
    Color ambient = reuse > 0 ? found.weighted / reuse : Color();
    if (ticket.depth == 0) {
        ++block.queries;
        block.reuse += reuse * 4;
    }
    const bool enough = reuse * 4 >= d.reuse_count ||
                        (final_trace && !s_.always_sample && reuse > 0);
    if (!enough) {
        Color gathered;
        const double quality = gather_light(at, normal, ticket, trace, &gathered);
        ambient = reuse > 0 ? (ambient * reuse + gathered * quality) / (reuse + quality)
                            : gathered;
        reuse += quality;
    }
    ticket.quality = std::min(4 * reuse / d.reuse_count, ticket.quality);
    ambient = ambient * (1.0 - s_.gray_threshold) + Color(s_.gray_threshold * greyscale(ambient));
    return ambient * s_.brightness;
}

double Radiosity::gather_light(const RadiosityPoint& at, const Vec3& normal,
                               RadiosityTicket& ticket, const RadiosityTraceFn& trace,
                               Color* illuminance) const {
    // GatherLight.
    const int depth = ticket.depth;
    const Depth& d = depths_[static_cast<size_t>(depth)];
    RadiosityBlock& block = *ticket.block;
    if (block.next_direction.size() < depths_.size()) block.next_direction.resize(depths_.size());
    const double to_eye = length(camera_ - at.p);
    const double reuse_min = to_eye * d.min_reuse;
    const double reuse_max = to_eye * d.max_reuse;
    const double saved_quality = ticket.quality;
    const double weight = std::max(s_.adc_bailout + kEpsilon, d.weight);

    int count = d.rays;
    bool use_raw = similar(at.raw_n, normal);
    Directions dirs(directions_, &block.next_direction[static_cast<size_t>(depth)]);
    dirs.start(&count, at.raw_n, normal, use_raw);
    double inverse_sum = 0, smallest = kInfinity, quality_sum = 0;
    Vec3 nearest_dir = normal;
    Color sum;
    int ok_count = 0, ok_raw = 0;
    for (int i = 0; i < count; ++i) {
        Vec3 dir;
        bool ok = dirs.next(&dir);
        if (!ok && !use_raw) {
            // Out of directions above the surface around the perturbed normal: the raw one.
            use_raw = true;
            dirs.start(&count, at.raw_n, normal, use_raw);
            ok = dirs.next(&dir);
        }
        if (!ok) break;
        ++ok_count;
        if (use_raw) ++ok_raw;
        ticket.quality = 1;
        Ray ray;
        ray.dir = dir;
        ray.origin = offset_ray_origin(at.p, at.p_error, at.ng, dir);
        ++ticket.depth;
        ticket.importance_queried = count > 1 ? static_cast<double>(i) / (count - 1) : 0.0;
        ticket.importance_found = 1;
        double hit = kInfinity;
        Color c = trace(ray, weight, d.trace_level, ticket, &hit);
        --ticket.depth;
        if (ticket.importance_found >= ticket.importance_queried) {
            double q = ticket.quality;
            if (ticket.importance_found < 1.0) {
                const double last = std::floor(ticket.importance_found * (count - 1));
                q *= static_cast<double>(count) / (last + 1);
            }
            // max_sample: no single ray brighter than this.
            const double brightest = c.max();
            if (s_.max_sample > 0 && brightest > s_.max_sample) c = c * (s_.max_sample / brightest);
            quality_sum += q;
            sum += c * q;
        }
        if (!(hit < kInfinity)) hit = kInfinity;
        if (hit < smallest) {
            smallest = hit;
            nearest_dir = dir;
        }
        inverse_sum += 1.0 / hit;
    }
    ticket.importance_queried = -1;
    *illuminance = quality_sum == 0 ? sum : sum / quality_sum;
    const double quality = ok_count > 0 ? quality_sum / ok_count : 0.0;
    // A sample whose rays almost all met something right away (two surfaces at once) is not
    // worth keeping.
    if (ok_count > 0 && smallest > reuse_max * 0.0001) {
        double mean = inverse_sum > 0 ? ok_count / inverse_sum : kInfinity;
        mean = std::clamp(mean, reuse_min, reuse_max);
        RadiositySample s;
        s.p = at.p;
        s.n = ok_raw > ok_count - ok_raw ? at.raw_n : normal;
        s.to_nearest = nearest_dir;
        s.irradiance = *illuminance;
        s.harmonic_mean = mean;
        s.nearest = smallest;
        s.quality = quality;
        s.depth = depth;
        block.local.add(s, mean * d.address_factor);
    }
    ticket.quality = std::max(saved_quality, quality);
    return quality;
}

RadiosityBlock* Radiosity::final_block(int index) const {
    if (index < 0 || index >= static_cast<int>(final_blocks_.size())) return nullptr;
    return final_blocks_[static_cast<size_t>(index)].get();
}

void Radiosity::start_final(int width, int height) {
    const int bx = (width + kBlockSize - 1) / kBlockSize, by = (height + kBlockSize - 1) / kBlockSize;
    final_blocks_.clear();
    for (int i = 0; i < bx * by; ++i) {
        final_blocks_.push_back(std::make_unique<RadiosityBlock>());
        final_blocks_.back()->pass = 0;
    }
}

// An image block and the parts of it the adaptive pretrace still refines.
struct Radiosity::PretraceBlock {
    int index = 0;
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // [x0, x1) x [y0, y1)
    int sub_x = 1, sub_y = 1;            // its subdivision
    std::deque<std::pair<int, int>> open{{0, 0}};  // sub-blocks not yet fine enough
    RadiosityBlock state;
};

void Radiosity::pretrace_block(PretraceBlock& b, int pass, int steps, double start, double end,
                               const PixelFn& pixel) const {
    // RadiosityTask::Run for one block and pass.
    const double size = std::max(start * std::pow(0.5, pass), end);
    const double next_size = std::max(start * std::pow(0.5, pass + 1), end);
    const int width = b.x1 - b.x0, height = b.y1 - b.y0;
    b.state = RadiosityBlock();
    b.state.pass = pass + 1;
    const int next_px = static_cast<int>((width + next_size - 1) / next_size);
    const int next_py = static_cast<int>((height + next_size - 1) / next_size);
    const double start_x = std::ceil((b.x0 - 0.5) / size) * size;
    const double start_y = std::ceil((b.y0 - 0.5) / size) * size;
    const double jitter = std::min(1.0, size / 2.0);
    const double offset = (size - 1.0) / 2.0;
    int divide_x = 1, divide_y = 1;
    if (s_.nearest_count_pretrace != 0) {
        // Subdivide for the next pass while that leaves at least 4 x 4 pixels.
        divide_x = std::max(1, next_px / (b.sub_x * 4));
        divide_y = std::max(1, next_py / (b.sub_y * 4));
    }
    uint64_t counter = 0;
    const size_t subs = b.open.size();
    for (size_t k = 0; k < subs; ++k) {
        const auto [sx, sy] = b.open.front();
        b.open.pop_front();
        b.state.queries = 0;
        b.state.reuse = 0;
        const double sub_x0 = b.x0 + static_cast<double>(width) * sx / b.sub_x;
        const double sub_x1 = sub_x0 + static_cast<double>(width) / b.sub_x;
        const double sub_y0 = b.y0 + static_cast<double>(height) * sy / b.sub_y;
        const double sub_y1 = sub_y0 + static_cast<double>(height) / b.sub_y;
        int pixels = 0;
        for (double y = start_y; y < sub_y1; y += size) {
            if (y < sub_y0) continue;
            for (double x = start_x; x < sub_x1; x += size) {
                if (x < sub_x0) continue;
                RadiosityTicket t;
                t.block = &b.state;
                t.pretrace = true;
                const double jx = jitter_number(pass, b.index, counter++);
                const double jy = jitter_number(pass, b.index, counter++);
                pixel(x + offset + jitter * jx, y + offset + jitter * jy, t);
                ++pixels;
            }
        }
        bool again;
        if (pixels < 9) again = true;  // at least a few pixels per sub-block
        else if (b.state.queries == 0) again = false;  // nothing here wants radiosity
        else if (s_.nearest_count_pretrace != 0 &&
                 b.state.reuse / static_cast<double>(b.state.queries) >= s_.nearest_count_pretrace)
            again = false;  // enough samples to reuse already
        else again = true;
        if (again)
            for (int dy = 0; dy < divide_y; ++dy)
                for (int dx = 0; dx < divide_x; ++dx)
                    b.open.emplace_back(sx * divide_x + dx, sy * divide_y + dy);
    }
    if (pass + 1 < steps && !b.open.empty()) {
        b.sub_x *= divide_x;
        b.sub_y *= divide_y;
    } else {
        b.open.clear();
    }
}

bool Radiosity::pretrace(int width, int height, int threads, const std::atomic<bool>* cancel,
                         const PixelFn& pixel) {
    // View::StartRender: the pretrace sizes in pixels and the number of passes.
    const double max_wh = std::max(width, height);
    double start = max_wh * s_.pretrace_start;
    const double end = std::max(1.0, max_wh * s_.pretrace_end);
    int steps = static_cast<int>(std::floor(std::log(start / end) / std::log(2.0) +
                                            (1.0 - kEpsilon))) + 1;
    constexpr int kMaxSteps = 251;  // OT_PASS_MAX - OT_PASS_FIRST - 1
    if (steps > kMaxSteps) {
        steps = kMaxSteps;
        start = end * std::pow(2.0, steps);
    }
    std::vector<PretraceBlock> blocks;
    for (int y = 0; y < height; y += kBlockSize)
        for (int x = 0; x < width; x += kBlockSize) {
            PretraceBlock b;
            b.index = static_cast<int>(blocks.size());
            b.x0 = x;
            b.y0 = y;
            b.x1 = std::min(x + kBlockSize, width);
            b.y1 = std::min(y + kBlockSize, height);
            blocks.push_back(std::move(b));
        }
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    for (int pass = 0; pass < steps; ++pass) {
        std::vector<size_t> todo;
        for (size_t i = 0; i < blocks.size(); ++i)
            if (!blocks[i].open.empty()) todo.push_back(i);
        if (todo.empty()) break;
        if (pass == 0) {
            // The first, coarsest pass runs block after block, each seeing the ones before:
            // it fills the deeper recursion depths, which every later block then reuses
            // instead of gathering its own (POV-Ray shares them across threads).
            for (size_t i : todo) {
                if (cancel && cancel->load(std::memory_order_relaxed)) return false;
                pretrace_block(blocks[i], pass, steps, start, end, pixel);
                cache_.merge(blocks[i].state.local);
            }
            continue;
        }
        std::atomic<bool> stopped{false};
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<size_t>(0, todo.size(), 1),
                              [&](const tbb::blocked_range<size_t>& r) {
                                  for (size_t i = r.begin(); i != r.end(); ++i) {
                                      if (cancel && cancel->load(std::memory_order_relaxed)) {
                                          stopped = true;
                                          return;
                                      }
                                      pretrace_block(blocks[todo[i]], pass, steps, start, end,
                                                     pixel);
                                  }
                              },
                              tbb::simple_partitioner());
        });
        if (stopped) return false;
        // The pass's samples join the cache in block order.
        for (size_t i : todo) cache_.merge(blocks[i].state.local);
    }
    return true;
}

}  // namespace glint::render
