// One scene object prepared for intersection: a primitive or a CSG tree behind its transform,
// with `inverse`, clipped_by, bounded_by, material inheritance and object flags applied.
// Geometry (geometry.cpp) holds one per top-level object; CSG nodes hold their children.
// All queries take a ray and points in the node's parent space.
#pragma once

#include <memory>
#include <vector>

#include "core/log.h"
#include "core/motion.h"
#include "core/transform.h"
#include "render/accel/bvh.h"
#include "render/shapes/primitive.h"
#include "scene/scene.h"

namespace glint::render {

// Mesh primitives of the scene's meshes, each built once and shared by every object that
// instances it (a scatter of 10,000 copies holds one BVH of the mesh, not 10,000).
struct SharedMeshes {
    std::vector<std::shared_ptr<const Primitive>> by_mesh;
    std::vector<char> tried;  // built (or found unusable) already
};

class ObjectNode {
public:
    // Builds the node for `obj`; returns nullptr (after a warning) for objects that cannot be
    // hit at all (degenerate shapes, empty meshes). Throws glint::Error on invalid input.
    // With `shared`, meshes behind a transform are built once per mesh and shared.
    static std::unique_ptr<ObjectNode> build(const scene::Object& obj, const scene::Scene& scene,
                                             Diagnostics& diag, SharedMeshes* shared = nullptr);

    // A node around a primitive made outside build() (merged meshes, geometry.cpp): `like`
    // gives the transform, material and flags (no inverse, clipping or bounding); with
    // `baked` the primitive has taken like.transform in.
    static std::unique_ptr<ObjectNode> wrap(std::unique_ptr<Primitive> prim,
                                            const scene::Object& like, bool baked);

    // Closest hit with 0 < t < tmax. With `shadow`, surfaces of no_shadow objects are ignored
    // (they still shape CSG results). A hit writes all of *hit; a miss leaves it alone.
    bool intersect(const Ray& ray, double tmax, bool shadow, LocalHit* hit) const;
    // intersect() without the last step when it can be left out: *deferred says whether the
    // hit is still in this node's object space, to be carried out by finish_deferred(). The
    // scene's BVH asks every candidate object and keeps one hit, so only that one pays for
    // the transform of its normals and error bound. (t is the same in both spaces.)
    bool intersect_deferred(const Ray& ray, double tmax, LocalHit* hit, bool* deferred) const;
    void finish_deferred(LocalHit* hit) const { finish(hit); }
    // Whether any shadow-casting surface lies at 0 < t < tmax.
    bool occludes(const Ray& ray, double tmax) const;
    // Every surviving hit with 0 < t < tmax, unsorted. With `points_only`, each hit's point is
    // carried into parent space but its normals and error bound are not (what shadow rays
    // through CSG need: where the surface is, to test it against the other children).
    void intersect_all(const Ray& ray, double tmax, HitList* hits,
                       bool points_only = false) const;
    // For a moving object: at the frame (shutter time 0.5); CSG and clipping, which ask this,
    // have no moving parts.
    bool inside(const Vec3& p) const;
    // Primitive::gradient_notes of every primitive in the tree, after the render.
    void gradient_notes(std::vector<GradientNote>* out) const;
    // Parent space; may be infinite. A moving object's holds it at every shutter time.
    const Bounds3& bounds() const { return bounds_; }
    uint32_t flags() const { return flags_; }

private:
    ObjectNode() = default;
    // The node's own surfaces before clipping, in parent space.
    bool intersect_unclipped(const Ray& ray, double tmax, bool shadow, LocalHit* hit) const;
    void intersect_all_unclipped(const Ray& ray, double tmax, HitList* hits,
                                 bool points_only) const;
    // In object space (the ray already transformed).
    bool intersect_local(const Ray& ray, double tmax, bool shadow, LocalHit* hit) const;
    void intersect_all_local(const Ray& ray, double tmax, HitList* hits, bool points_only) const;
    // Whether a shadow-casting surface of this CSG (not a union) lies at 0 < t < tmax, in
    // object space: stops at the first surface the operation keeps.
    bool csg_occludes(const Ray& ray, double tmax) const;
    bool inside_local(const Vec3& p) const;
    bool csg_keeps(size_t child, const Vec3& p) const;
    bool passes_bound(const Ray& ray) const;
    bool passes_clip(const Vec3& p) const;
    // Object space -> parent space, with inverse/material/flags applied.
    void finish(LocalHit* h) const;
    void finish_point(LocalHit* h) const;
    void compute_bounds();
    // Where this node's solid can lie within `box` (its parent's space): a quadric in a CSG
    // intersection is bounded by its partners (Primitive::bounds_within).
    Bounds3 bounds_within(const Bounds3& box) const;
    void build_child_bvh();
    bool union_intersect(const Ray& ray, double tmax, bool shadow, LocalHit* hit) const;

    // A moving object (scene::Object::motion): still_ is the object in its own space, and
    // rays meet it through the transform at their time. Every query checks motion_ first.
    bool moving_query(const Ray& ray, Transform* at, Ray* local) const;
    std::unique_ptr<const MotionTransform> motion_;
    std::unique_ptr<ObjectNode> still_;

    Transform xf_;
    bool identity_ = true;
    std::shared_ptr<const Primitive> prim_;  // leaf (shared between instances of a mesh), or:
    bool whole_hit_ = false;           // prim_->writes_whole_hit()
    bool is_csg_ = false;
    scene::CsgOp op_ = scene::CsgOp::Union;
    std::vector<std::unique_ptr<ObjectNode>> children_;
    // Unions of many children (POV-Ray #while loops) get a BVH over the bounded ones.
    Bvh child_bvh_;
    std::vector<int> unbounded_children_;
    bool inverse_ = false;
    int material_ = -1;
    // A mesh's face materials as this object has them (scene::MeshRef::face_materials).
    std::vector<std::pair<int, int>> face_materials_;
    uint32_t flags_ = 0;
    std::vector<std::unique_ptr<ObjectNode>> bounded_by_;
    std::vector<std::unique_ptr<ObjectNode>> clipped_by_;
    Bounds3 bounds_;
};

// Carries an object-space hit into the parent space of `xf`: the point with its error bound
// (pbrt-v4 Transform::operator()(Point3fi)), normals by the inverse transpose, renormalized.
void transform_hit(const Transform& xf, LocalHit* h);

}  // namespace glint::render
