// The irradiance cache of POV-Ray 3.7's radiosity (backend/lighting/radiosity.cpp
// RadiosityCache, backend/support/octree.cpp): samples of the indirect light, filed in an
// octree of power-of-two cubes by their radius of influence, and the weighted average of those
// that may stand in for a new one (Ward's error estimate as POV-Ray extends it).
//
// The octree is kept as a hash of its nodes: a sample is filed in the smallest cube (with
// POV-Ray's half-cube overhang on every side) that holds its influence sphere, and a lookup
// visits the cubes whose overhanging extent holds the point, so the cache finds exactly the
// samples POV-Ray's tree traversal finds.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/math.h"
#include "scene/color.h"

namespace glint::render {

// One cached sample (octree.h OT_BLOCK).
struct RadiositySample {
    Vec3 p;           // where it was taken
    Vec3 n;           // the normal it was taken for
    Vec3 to_nearest;  // unit direction of the nearest surface its rays met
    Color irradiance;
    double harmonic_mean = 0;  // harmonic mean distance of its rays' hits (clamped)
    double nearest = 0;        // distance of the nearest hit
    double quality = 1;        // share of its rays that met good samples in turn
    int depth = 0;             // radiosity recursion depth it serves
};

// What a lookup found: the sum of the usable samples' weights and of their weighted
// irradiance (FindReusableBlock before its division).
struct RadiosityReuse {
    double weight = 0;
    Color weighted;
};

class RadiosityCache {
public:
    // Files `s` under the cube that holds the sphere of `address_radius` around s.p.
    void add(const RadiositySample& s, double address_radius);
    // AverageNearBlock over the samples of depth `depth` whose cubes hold `p`: those within
    // `error_bound` by Ward's translation-plus-rotation error and not well in front of `p`,
    // each weighted by its quality. `smooth`: the final render's top level, where POV-Ray
    // weights by a pseudo-sigmoid rather than linearly. Adds to `out`.
    void gather(const Vec3& p, const Vec3& n, int depth, double error_bound, bool smooth,
                RadiosityReuse* out) const;
    // Adds every sample of `other`, in its order.
    void merge(const RadiosityCache& other);
    size_t size() const { return samples_.size(); }
    const std::vector<RadiositySample>& samples() const { return samples_; }

private:
    struct Key {
        int depth, level;
        int64_t x, y, z;
        bool operator==(const Key& o) const {
            return depth == o.depth && level == o.level && x == o.x && y == o.y && z == o.z;
        }
    };
    struct KeyHash {
        size_t operator()(const Key& k) const;
    };
    std::vector<RadiositySample> samples_;
    std::vector<double> address_radius_;  // per sample, for merge()
    std::unordered_map<Key, std::vector<uint32_t>, KeyHash> cells_;
    // The cube sizes (log2) in use, per depth, ascending.
    std::vector<std::vector<int>> levels_;
};

}  // namespace glint::render
