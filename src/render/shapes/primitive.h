// The shape interface behind Geometry: one primitive in its own object space answers closest
// hit, all hits along a ray (CSG needs the entering/leaving intervals) and point containment.
// Used by the object tree (object_node.h), which adds transforms, CSG, clipping and inverse.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/float.h"
#include "core/math.h"
#include "render/ray.h"

namespace glint::render {

// A surface hit in the space of whoever computed it; the object tree carries it up to world
// space through each transform (points with their error bounds, normals by inverse transpose).
struct LocalHit {
    double t = kInfinity;
    Vec3 p;        // hit point, lies within p +- p_error of the true surface
    Vec3 p_error;  // absolute error bound of p
    Vec3 ng;       // geometric normal, unit, outward for solids
    Vec3 n;        // shading normal, unit, same side as ng
    Vec2 uv;
    bool has_uv = false;
    int material = -1;   // -1: inherit from the enclosing object
    uint32_t flags = 0;  // ObjectFlags accumulated on the way up
};

class Primitive {
public:
    virtual ~Primitive() = default;
    // Object-space bounds; infinite for unbounded shapes (planes).
    virtual Bounds3 bounds() const = 0;
    // Closest hit with 0 < t < tmax.
    virtual bool intersect(const Ray& ray, double tmax, LocalHit* hit) const = 0;
    // Appends every hit with 0 < t < tmax, in any order.
    virtual void intersect_all(const Ray& ray, double tmax, std::vector<LocalHit>* hits) const = 0;
    // POV-Ray's inside test (CSG); shapes without an inside (triangles, discs) return false.
    virtual bool inside(const Vec3& p) const = 0;
};

// Hit points refined onto the surface keep an error bound proportional to their magnitude.
inline Vec3 rounding_error(const Vec3& p, int n) { return abs(p) * gamma(n); }

}  // namespace glint::render
