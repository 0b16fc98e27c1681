// The shape interface behind Geometry: one primitive in its own object space answers closest
// hit, all hits along a ray (CSG needs the entering/leaving intervals) and point containment.
// Used by the object tree (object_node.h), which adds transforms, CSG, clipping and inverse.
#pragma once

#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
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
    // uv that needs trigonometry is computed once, for the final hit only: the primitive and
    // the object-space point it needs (uv_source->uv_at(uv_point)). A blob with component
    // textures names itself here too, for its texture_blend().
    const class Primitive* uv_source = nullptr;
    Vec3 uv_point;
    Vec3 dpdu, dpdv;     // uv tangents where known (meshes with uvs), else zero
    int material = -1;   // -1: inherit from the enclosing object
    uint32_t flags = 0;  // ObjectFlags accumulated on the way up
    AttributePoint attributes;  // meshes with named attributes
};

// One texture of a blend: a Scene::materials id (-1: the object's own) and its weight.
struct TextureWeight {
    int material = -1;
    double weight = 0;
};

// Hits along one ray, kept on the stack for the usual handful (CSG asks for every hit of every
// child on every ray, so a heap allocation per query would dominate).
class HitList {
public:
    static constexpr size_t kInline = 8;
    HitList() = default;
    HitList(const HitList&) = delete;
    HitList& operator=(const HitList&) = delete;

    LocalHit& emplace_back() {
        if (!spilled_ && n_ < kInline) return *new (inline_ + n_++ * sizeof(LocalHit)) LocalHit();
        if (!spilled_) {
            heap_.assign(begin(), end());
            spilled_ = true;
        }
        ++n_;
        return heap_.emplace_back();
    }
    void push_back(const LocalHit& h) { emplace_back() = h; }
    size_t size() const { return n_; }
    bool empty() const { return n_ == 0; }
    LocalHit* begin() {
        return spilled_ ? heap_.data() : std::launder(reinterpret_cast<LocalHit*>(inline_));
    }
    LocalHit* end() { return begin() + n_; }
    const LocalHit* begin() const {
        return spilled_ ? heap_.data()
                        : std::launder(reinterpret_cast<const LocalHit*>(inline_));
    }
    const LocalHit* end() const { return begin() + n_; }
    LocalHit& operator[](size_t i) { return begin()[i]; }
    const LocalHit& operator[](size_t i) const { return begin()[i]; }
    // Keeps the first n hits.
    void truncate(size_t n) {
        if (n >= n_) return;
        n_ = n;
        if (spilled_) heap_.resize(n);
    }
    void clear() { truncate(0); }

private:
    // Raw storage, made into hits only as they are added: a HitList is made per CSG query, and
    // constructing all eight 240-byte hits up front cost more than most queries.
    static_assert(std::is_trivially_destructible_v<LocalHit>);
    alignas(LocalHit) unsigned char inline_[kInline * sizeof(LocalHit)];
    std::vector<LocalHit> heap_;
    size_t n_ = 0;
    bool spilled_ = false;
};

// POV-Ray's advice after the render of an isosurface: the steepest gradient its root search met
// against the max_gradient it was given. Copies of one isosurface share `function`.
struct GradientNote {
    int function = -1;
    double found = 0, given = 0;
    bool evaluate = false;
};

class Primitive {
public:
    virtual ~Primitive() = default;
    // Object-space bounds; infinite for unbounded shapes (planes).
    virtual Bounds3 bounds() const = 0;
    // Closest hit with 0 < t < tmax.
    virtual bool intersect(const Ray& ray, double tmax, LocalHit* hit) const = 0;
    // Appends every hit with 0 < t < tmax, in any order.
    virtual void intersect_all(const Ray& ray, double tmax, HitList* hits) const = 0;
    // intersect_all() for shadow rays through CSG, which read only each hit's t and p: shapes
    // whose normals or uv cost something may leave them out.
    virtual void intersect_all_points(const Ray& ray, double tmax, HitList* hits) const {
        intersect_all(ray, tmax, hits);
    }
    // Any hit with 0 < t < tmax (shadow rays); shapes with many surfaces stop at the first.
    virtual bool occludes(const Ray& ray, double tmax) const {
        LocalHit h;
        return intersect(ray, tmax, &h);
    }
    // Whether intersect() leaves *hit alone on a miss and, on a hit, writes all of it (every
    // field as a fresh LocalHit would have it): then callers need no fresh LocalHit per query.
    virtual bool writes_whole_hit() const { return false; }
    // Deferred uv (see LocalHit::uv_source).
    virtual Vec2 uv_at(const Vec3&) const { return {}; }
    // Shapes whose parts have textures of their own (blob components): the textures that
    // blend at the final hit's uv_point (see LocalHit::uv_source), as Scene::materials ids
    // (-1: the object's own) with weights summing to 1. False: the object's material alone.
    virtual bool texture_blend(const Vec3& /*p*/, std::vector<TextureWeight>* /*out*/) const {
        return false;
    }
    // Where the shape's inside (and surface) can lie within `box`, for a CSG intersection's
    // bounds: by default the overlap of its bounds with the box; an unbounded quadric can do
    // better (its extent where its partners leave it).
    virtual Bounds3 bounds_within(const Bounds3& box) const {
        const Bounds3 b = bounds();
        return {max(b.lo, box.lo), min(b.hi, box.hi)};
    }
    // POV-Ray's inside test (CSG); shapes without an inside (triangles, discs) return false.
    virtual bool inside(const Vec3& p) const = 0;
    // After the render: what POV-Ray would report (isosurfaces only).
    virtual void gradient_notes(std::vector<GradientNote>*) const {}

protected:
    // intersect() for shapes whose hits all come from one pass (root finding over a sweep,
    // a polynomial, glyph outlines): the nearest of intersect_all()'s, the first of equal t.
    bool nearest_of_all(const Ray& ray, double tmax, LocalHit* hit) const {
        HitList hits;
        intersect_all(ray, tmax, &hits);
        if (hits.empty()) return false;
        const LocalHit* best = &hits[0];
        for (const LocalHit& h : hits)
            if (h.t < best->t) best = &h;
        *hit = *best;
        return true;
    }
};

// Hit points refined onto the surface keep an error bound proportional to their magnitude.
inline Vec3 rounding_error(const Vec3& p, int n) { return abs(p) * gamma(n); }

}  // namespace glint::render
