#include "render/gi/radiosity_cache.h"

#include <algorithm>
#include <cmath>

namespace glint::render {
namespace {

// octree.h OT_BIAS: shifts the scene so cube indices stay positive.
constexpr double kBias = 10000000.0;
// radiosity.cpp: AVG_NEAR_EPSILON, RAD_EPSILON and IN_FRONT_LIMIT.
constexpr double kNearEpsilon = 0.000001;
constexpr double kWeightEpsilon = 0.001;
constexpr double kInFrontLimit = -0.05;

// Cube indices stay well inside int64 and exact in a double.
constexpr double kMaxIndex = 1.0e15;

double cube_size(int level) { return std::ldexp(1.0, level); }

// ot_point_in_node: `q` lies within the cube's extent widened by half a cube on every side.
bool in_cube(const Vec3& q, int level, int64_t x, int64_t y, int64_t z) {
    const double s = cube_size(level);
    return std::fabs(q.x + kBias - (static_cast<double>(x) + 0.5) * s) < s &&
           std::fabs(q.y + kBias - (static_cast<double>(y) + 0.5) * s) < s &&
           std::fabs(q.z + kBias - (static_cast<double>(z) + 0.5) * s) < s;
}

}  // namespace

size_t RadiosityCache::KeyHash::operator()(const Key& k) const {
    uint64_t h = static_cast<uint64_t>(k.depth) * 0x9E3779B97F4A7C15ull;
    for (uint64_t v : {static_cast<uint64_t>(k.level), static_cast<uint64_t>(k.x),
                       static_cast<uint64_t>(k.y), static_cast<uint64_t>(k.z)}) {
        h ^= v + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    }
    return static_cast<size_t>(h);
}

void RadiosityCache::add(const RadiositySample& s, double address_radius) {
    // ot_index_sphere / ot_index_box: the power of two at or below the sphere's diameter,
    // the cube holding its centre, then parents until both box corners lie in the extent.
    // A sample must sit somewhere finite to be filed; its reach is kept finite (a huge
    // maximum_reuse can make it infinite) so the cube search ends.
    if (!std::isfinite(s.p.x + s.p.y + s.p.z)) return;
    const double r = address_radius >= 0 ? std::min(address_radius, 1.0e30) : 0.0;
    const Vec3 lo = s.p - Vec3(r), hi = s.p + Vec3(r);
    int level = 0;
    if (2 * r > 0) {
        int e;
        std::frexp(2 * r, &e);
        level = e - 1;
    }
    const double far = std::max({std::fabs(lo.x), std::fabs(lo.y), std::fabs(lo.z),
                                 std::fabs(hi.x), std::fabs(hi.y), std::fabs(hi.z)}) +
                       kBias;
    while (far / cube_size(level) > kMaxIndex) ++level;
    const double size = cube_size(level);
    int64_t x = static_cast<int64_t>(std::floor((s.p.x + kBias) / size));
    int64_t y = static_cast<int64_t>(std::floor((s.p.y + kBias) / size));
    int64_t z = static_cast<int64_t>(std::floor((s.p.z + kBias) / size));
    while (!in_cube(lo, level, x, y, z) || !in_cube(hi, level, x, y, z)) {
        ++level;
        x >>= 1;
        y >>= 1;
        z >>= 1;
    }
    const uint32_t index = static_cast<uint32_t>(samples_.size());
    samples_.push_back(s);
    address_radius_.push_back(address_radius);
    cells_[Key{s.depth, level, x, y, z}].push_back(index);
    if (static_cast<int>(levels_.size()) <= s.depth) levels_.resize(s.depth + 1);
    std::vector<int>& lv = levels_[s.depth];
    auto it = std::lower_bound(lv.begin(), lv.end(), level);
    if (it == lv.end() || *it != level) lv.insert(it, level);
}

void RadiosityCache::merge(const RadiosityCache& other) {
    for (size_t i = 0; i < other.samples_.size(); ++i)
        add(other.samples_[i], other.address_radius_[i]);
}

void RadiosityCache::gather(const Vec3& p, const Vec3& n, int depth, double error_bound,
                            bool smooth, RadiosityReuse* out) const {
    if (depth < 0 || depth >= static_cast<int>(levels_.size())) return;
    auto use = [&](const RadiositySample& b) {
        // AverageNearBlock.
        const Vec3 delta = p - b.p;
        const double square_dist = dot(delta, delta);
        const double quick = b.harmonic_mean * error_bound;
        if (!(square_dist < quick * quick)) return;
        const double dist = std::sqrt(square_dist);
        double ri = b.harmonic_mean;
        const bool apart = dist > kNearEpsilon;
        Vec3 delta_unit;
        if (apart) {
            delta_unit = delta / dist;
            // Less reach towards the nearest surface the sample's rays met.
            const double c = dot(b.to_nearest, delta_unit);
            if (c > 0) ri = c * b.nearest + (1 - c) * ri;
        }
        if (!(dist < ri * error_bound)) return;
        const double error = dist / ri + 2.0 * std::sqrt(std::fabs(1.0 - dot(n, b.n)));
        if (!(error < error_bound)) return;
        double in_front = 1;
        if (apart) {
            const Vec3 half = n + b.n;
            in_front = dot(delta_unit, half) / length(half);
        }
        if (!(in_front > kInFrontLimit)) return;
        double w = error / error_bound;
        if (smooth)
            w = w < 0.5 ? 1 - (w * 2) * (w * 2) / 2 : ((1 - w) * 2) * ((1 - w) * 2) / 2;
        else
            w = 1 - w;
        if (in_front <= 0) w *= 1 - in_front / kInFrontLimit;
        if (!(w > kWeightEpsilon)) return;
        w *= b.quality;
        out->weighted += b.irradiance * w;
        out->weight += w;
    };
    for (int level : levels_[depth]) {
        const double s = cube_size(level);
        int64_t base[3];
        const double q[3] = {p.x, p.y, p.z};
        for (int a = 0; a < 3; ++a)
            base[a] = static_cast<int64_t>(std::floor((q[a] + kBias) / s - 1.5)) + 1;
        for (int64_t dz = 0; dz < 2; ++dz)
            for (int64_t dy = 0; dy < 2; ++dy)
                for (int64_t dx = 0; dx < 2; ++dx) {
                    const int64_t x = base[0] + dx, y = base[1] + dy, z = base[2] + dz;
                    if (!in_cube(p, level, x, y, z)) continue;
                    auto it = cells_.find(Key{depth, level, x, y, z});
                    if (it == cells_.end()) continue;
                    for (uint32_t i : it->second) use(samples_[i]);
                }
    }
}

}  // namespace glint::render
