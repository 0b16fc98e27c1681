#include "render/shapes/object_node.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/float.h"
#include "render/shapes/mesh/mesh_prim.h"
#include "render/shapes/shapes.h"
#include "render/shapes/text/text.h"

namespace glint::render {

namespace {
// |M| e for the linear part of M: how an error box maps through the transform.
Vec3 map_error(const Matrix4& mat, const Vec3& e) {
    const auto& m = mat.m;
    Vec3 r;
    for (int i = 0; i < 3; ++i)
        r[i] = (1 + gamma(3)) *
               (std::fabs(m[i][0]) * e.x + std::fabs(m[i][1]) * e.y + std::fabs(m[i][2]) * e.z);
    return r;
}
}  // namespace

void transform_hit(const Transform& xf, LocalHit* h) {
    Vec3 p = xf.point(h->p);
    // The bound covers the forward transform of the point and its error, and also the rounding
    // that taking a ray origin near p back into object space will add (mapped to this space):
    // a secondary ray offset by it is still on the right side once it is in object space.
    Vec3 back = map_error(xf.matrix(), xf.inverse().point_error(p));
    h->p_error = map_error(xf.matrix(), h->p_error) + xf.point_error(h->p) + back;
    h->p = p;
    h->ng = normalize(xf.normal(h->ng));
    h->n = normalize(xf.normal(h->n));
    if (h->has_uv) {
        h->dpdu = xf.vector(h->dpdu);
        h->dpdv = xf.vector(h->dpdv);
    }
}

namespace {

uint32_t object_flags(const scene::Object& o) {
    uint32_t f = 0;
    if (o.no_shadow) f |= kNoShadow;
    if (o.no_image) f |= kNoImage;
    if (o.no_reflection) f |= kNoReflection;
    if (o.double_illuminate) f |= kDoubleIlluminate;
    if (o.no_radiosity) f |= kNoRadiosity;
    if (o.no_global_lights) f |= kNoGlobalLights;
    if (o.hollow) f |= kHollow;
    return f | light_group_flags(o.light_group);
}

Bounds3 overlap(const Bounds3& a, const Bounds3& b) { return {max(a.lo, b.lo), min(a.hi, b.hi)}; }

const Bounds3 kEverywhere{Vec3(-kInfinity), Vec3(kInfinity)};

struct Builder {
    const scene::Scene& scene;
    Diagnostics& diag;
    // Set when the primitive took obj.transform into itself (the node then has none).
    bool baked = false;
    SharedMeshes* shared = nullptr;

    std::shared_ptr<const Primitive> primitive(const scene::Object& obj, Transform* frame) {
        const char* why = nullptr;
        std::unique_ptr<Primitive> p;
        *frame = Transform();
        // An instanced mesh: the one primitive of its mesh, whatever transform places it.
        if (const auto* ref = std::get_if<scene::MeshRef>(&obj.shape);
            ref && shared && ref->mesh >= 0 &&
            ref->mesh < static_cast<int>(scene.meshes.size()) && !bake_exact(obj.transform)) {
            const size_t id = static_cast<size_t>(ref->mesh);
            if (shared->by_mesh.size() < scene.meshes.size()) {
                shared->by_mesh.resize(scene.meshes.size());
                shared->tried.resize(scene.meshes.size());
            }
            if (!shared->tried[id]) {
                shared->tried[id] = 1;
                shared->by_mesh[id] = make_mesh(scene.meshes[id], diag, nullptr);
                if (!shared->by_mesh[id])
                    diag.warning(obj.loc, "mesh without usable triangles: object skipped");
            }
            return shared->by_mesh[id];
        }
        std::visit(
            [&](const auto& s) {
                using T = std::decay_t<decltype(s)>;
                if constexpr (std::is_same_v<T, scene::Sphere>) {
                    p = make_sphere(s);
                    if (!(s.radius != 0) || !std::isfinite(s.radius) || !is_finite(s.center))
                        why = "sphere with zero or non-finite radius or centre";
                } else if constexpr (std::is_same_v<T, scene::Plane>) {
                    if (!(length_squared(s.normal) > 0) || !is_finite(s.normal) ||
                        !std::isfinite(s.distance))
                        why = "plane with a zero or non-finite normal";
                    else
                        p = make_plane(s);
                } else if constexpr (std::is_same_v<T, scene::Box>) {
                    if (!is_finite(s.corner1) || !is_finite(s.corner2))
                        why = "box with non-finite corners";
                    else
                        p = make_box(s);
                } else if constexpr (std::is_same_v<T, scene::Cylinder>) {
                    p = make_cylinder(s, frame, &why);
                } else if constexpr (std::is_same_v<T, scene::Cone>) {
                    p = make_cone(s, frame, &why);
                } else if constexpr (std::is_same_v<T, scene::Disc>) {
                    p = make_disc(s, frame, &why);
                } else if constexpr (std::is_same_v<T, scene::Torus>) {
                    if (!(s.major > 0) || !(s.minor > 0) || !std::isfinite(s.major) ||
                        !std::isfinite(s.minor))
                        why = "torus with non-positive or non-finite radii";
                    else
                        p = make_torus(s);
                } else if constexpr (std::is_same_v<T, scene::Triangle>) {
                    p = make_triangle(s.p, nullptr);
                    if (!p) why = "degenerate triangle (zero area or non-finite vertices)";
                } else if constexpr (std::is_same_v<T, scene::SmoothTriangle>) {
                    p = make_triangle(s.p, s.n);
                    if (!p) why = "degenerate smooth_triangle (zero area or non-finite vertices)";
                } else if constexpr (std::is_same_v<T, scene::Text>) {
                    p = make_text(s, obj.loc, &why);
                } else if constexpr (std::is_same_v<T, scene::MeshRef>) {
                    if (s.mesh < 0 || s.mesh >= static_cast<int>(scene.meshes.size()))
                        throw Error(ErrorKind::Scene, obj.loc, "mesh reference out of range");
                    // obj_file's mirror is baked into the mesh: rays skip the transform.
                    // (A deforming mesh keeps its transform: it has no baked form.)
                    baked = bake_exact(obj.transform) &&
                            scene.meshes[s.mesh].motion_positions.empty();
                    p = make_mesh(scene.meshes[s.mesh], diag, baked ? &obj.transform : nullptr);
                    if (!p) why = "mesh without usable triangles";
                } else if constexpr (std::is_same_v<T, scene::Quadric>) {
                    p = make_quadric(s, &why);
                } else if constexpr (std::is_same_v<T, scene::Polygon>) {
                    p = make_polygon(s, &why);
                } else if constexpr (std::is_same_v<T, scene::Prism>) {
                    p = make_prism(s, &why);
                } else if constexpr (std::is_same_v<T, scene::Lathe>) {
                    p = make_lathe(s, &why);
                } else if constexpr (std::is_same_v<T, scene::Sor>) {
                    p = make_sor(s, &why);
                } else if constexpr (std::is_same_v<T, scene::Superellipsoid>) {
                    p = make_superellipsoid(s, &why);
                } else if constexpr (std::is_same_v<T, scene::Blob>) {
                    p = make_blob(s, &why);
                } else if constexpr (std::is_same_v<T, scene::HeightField>) {
                    p = make_height_field(s, obj.loc, obj.transform, &why);
                } else if constexpr (std::is_same_v<T, scene::Poly>) {
                    p = make_poly(s, &why);
                } else if constexpr (std::is_same_v<T, scene::JuliaFractal>) {
                    p = make_julia_fractal(s, obj.transform, &why);
                } else if constexpr (std::is_same_v<T, scene::BicubicPatch>) {
                    baked = true;
                    p = make_bicubic_patch(s, obj.transform, &why);
                } else if constexpr (std::is_same_v<T, scene::Isosurface>) {
                    p = make_isosurface(s, scene, &why);
                } else if constexpr (std::is_same_v<T, scene::SphereSweep>) {
                    p = make_sphere_sweep(s, &why);
                } else if constexpr (std::is_same_v<T, scene::Ovus>) {
                    p = make_ovus(s, &why);
                } else if constexpr (std::is_same_v<T, scene::Parametric>) {
                    p = make_parametric(s, scene, obj.transform, &why);
                }
            },
            obj.shape);
        if (why) {
            diag.warning(obj.loc, std::string(why) + ": object skipped");
            return nullptr;
        }
        return p;
    }
};

// `inverse` on a CSG as POV-Ray applies it (CSG::Invert, then Morph): every child inverted
// and the operation swapped by De Morgan's laws, union and merge becoming an intersection, an
// intersection a merge, so that the surfaces kept are those of the complement. (Inverting
// only the inside test would keep a union's inner walls, which its complement hides.)
scene::Object inverted_csg(const scene::Object& obj) {
    scene::Object out = obj;
    out.inverse = false;
    scene::Csg& csg = std::get<scene::Csg>(out.shape);
    switch (csg.op) {
        case scene::CsgOp::Union:
        case scene::CsgOp::Merge:
            csg.op = scene::CsgOp::Intersection;
            for (scene::Object& c : csg.children) c.inverse = !c.inverse;
            break;
        case scene::CsgOp::Intersection:
            csg.op = scene::CsgOp::Merge;
            for (scene::Object& c : csg.children) c.inverse = !c.inverse;
            break;
        case scene::CsgOp::Difference:
            // a - b - c is a * inverse(b) * inverse(c); its inverse, inverse(a) + b + c.
            csg.op = scene::CsgOp::Merge;
            if (!csg.children.empty()) csg.children[0].inverse = !csg.children[0].inverse;
            break;
    }
    return out;
}

}  // namespace

std::unique_ptr<ObjectNode> ObjectNode::build(const scene::Object& obj,
                                              const scene::Scene& scene, Diagnostics& diag,
                                              SharedMeshes* shared) {
    if (!obj.motion.empty()) {
        // The object built where it is in its own space (a shared mesh stays shared), moved
        // per ray.
        scene::Object still = obj;
        still.motion.clear();
        still.transform = Transform();
        auto inner = build(still, scene, diag, shared);
        if (!inner) return nullptr;
        std::unique_ptr<ObjectNode> node(new ObjectNode());
        node->material_ = inner->material_;
        node->flags_ = inner->flags_;
        node->motion_ = std::make_unique<const MotionTransform>(obj.motion);
        node->bounds_ = node->motion_->bounds(inner->bounds());
        node->xf_ = obj.transform;
        node->identity_ = false;
        node->still_ = std::move(inner);
        return node;
    }
    if (obj.inverse && std::holds_alternative<scene::Csg>(obj.shape))
        return build(inverted_csg(obj), scene, diag, shared);
    std::unique_ptr<ObjectNode> node(new ObjectNode());
    node->inverse_ = obj.inverse;
    node->material_ = obj.material;
    node->flags_ = object_flags(obj);
    if (const auto* ref = std::get_if<scene::MeshRef>(&obj.shape))
        node->face_materials_ = ref->face_materials;
    Transform frame;
    bool baked = false;
    if (const auto* csg = std::get_if<scene::Csg>(&obj.shape)) {
        node->is_csg_ = true;
        node->op_ = csg->op;
        for (size_t i = 0; i < csg->children.size(); ++i) {
            auto child = build(csg->children[i], scene, diag);
            if (child) {
                node->children_.push_back(std::move(child));
                continue;
            }
            // A missing child removes nothing from a union, merge or cut; an intersection with
            // it, or a difference of it, is empty.
            bool essential = csg->op == scene::CsgOp::Intersection ||
                             (csg->op == scene::CsgOp::Difference && i == 0);
            if (essential) return nullptr;
        }
        if (node->children_.empty()) return nullptr;
    } else {
        Builder b{scene, diag, false, shared};
        node->prim_ = b.primitive(obj, &frame);
        if (!node->prim_) return nullptr;
        baked = b.baked;
        node->whole_hit_ = node->prim_->writes_whole_hit();
    }
    node->xf_ = baked ? frame : frame.then(obj.transform);
    node->identity_ = node->xf_.is_identity();
    for (const auto& b : obj.bounded_by)
        if (auto n = build(b, scene, diag)) node->bounded_by_.push_back(std::move(n));
    for (const auto& c : obj.clipped_by) {
        auto n = build(c, scene, diag);
        if (!n) return nullptr;  // clipping by nothing leaves nothing
        node->clipped_by_.push_back(std::move(n));
    }
    node->compute_bounds();
    node->build_child_bvh();
    return node;
}

std::unique_ptr<ObjectNode> ObjectNode::wrap(std::unique_ptr<Primitive> prim,
                                             const scene::Object& like, bool baked) {
    if (!prim) return nullptr;
    std::unique_ptr<ObjectNode> node(new ObjectNode());
    node->material_ = like.material;
    node->flags_ = object_flags(like);
    node->prim_ = std::move(prim);
    node->whole_hit_ = node->prim_->writes_whole_hit();
    node->xf_ = baked ? Transform() : like.transform;
    node->identity_ = node->xf_.is_identity();
    node->compute_bounds();
    return node;
}

void ObjectNode::compute_bounds() {
    Bounds3 local;
    if (prim_) {
        local = prim_->bounds();
    } else if (op_ == scene::CsgOp::Intersection) {
        local = kEverywhere;
        for (const auto& c : children_) local = overlap(local, c->bounds());
        // Unbounded quadrics between planes (shapes.inc's Cylinder_Y, Hyperboloid_Y cut to a
        // height) are finite there, as POV-Ray's bounding boxes find: twice, since each
        // axis bounded can bound the others.
        for (int pass = 0; pass < 2 && !local.empty() && local.is_infinite(); ++pass)
            for (const auto& c : children_) local = overlap(local, c->bounds_within(local));
    } else if (op_ == scene::CsgOp::Difference) {
        local = children_[0]->bounds();
    } else {
        for (const auto& c : children_) local.extend(c->bounds());
    }
    bounds_ = (local.empty() || identity_) ? local : xf_.bounds(local);
    if (inverse_) bounds_ = kEverywhere;
    for (const auto& c : clipped_by_) bounds_ = overlap(bounds_, c->bounds());
}

void ObjectNode::build_child_bvh() {
    constexpr size_t kMinChildren = 4;
    if (!is_csg_ || op_ != scene::CsgOp::Union || children_.size() < kMinChildren) return;
    std::vector<Bounds3> boxes;
    for (size_t i = 0; i < children_.size(); ++i) {
        boxes.push_back(children_[i]->bounds());
        if (boxes.back().is_infinite()) unbounded_children_.push_back(static_cast<int>(i));
    }
    child_bvh_ = Bvh(boxes, 2);
}

bool ObjectNode::union_intersect(const Ray& ray, double tmax, bool shadow, LocalHit* hit) const {
    if (child_bvh_.empty() && unbounded_children_.empty()) {
        bool found = false;
        for (const auto& c : children_) {
            // Later children must be strictly closer: ties go to the earlier child.
            if (c->intersect(ray, found ? hit->t : tmax, shadow, hit)) found = true;
        }
        return found;
    }
    // Through the children's BVH; equal t still goes to the lower child index.
    int best = -1;
    auto visit = [&](int i, double& t) {
        LocalHit h;
        double limit = best < 0 ? t : next_up(hit->t);
        if (children_[i]->intersect(ray, limit, shadow, &h) &&
            (best < 0 || h.t < hit->t || i < best)) {
            *hit = h;
            best = i;
            t = h.t;
        }
        return false;
    };
    double t = tmax;
    child_bvh_.traverse(ray, t, visit);
    for (int i : unbounded_children_) visit(i, t);
    return best >= 0;
}

void ObjectNode::finish_point(LocalHit* h) const {
    if (!identity_) h->p = xf_.point(h->p);
    add_object_flags(&h->flags, flags_);
}

void ObjectNode::finish(LocalHit* h) const {
    if (!identity_) transform_hit(xf_, h);
    if (inverse_) {
        h->ng = -h->ng;
        h->n = -h->n;
    }
    if (h->material < 0) {
        h->material = material_;
    } else {
        for (const auto& [from, to] : face_materials_)
            if (h->material == from) {
                h->material = to;
                break;
            }
    }
    add_object_flags(&h->flags, flags_);
}

namespace {
// Transform::inverse_point and inverse_vector written out here, operation for operation (the
// same results), so that this, done for every candidate object of every ray, is not two calls.
Ray to_local(const Transform& xf, bool identity, const Ray& ray) {
    if (identity) return ray;
    const auto& a = xf.inverse_matrix().m;
    const Vec3 &p = ray.origin, &v = ray.dir;
    return {{a[0][0] * p.x + a[0][1] * p.y + a[0][2] * p.z + a[0][3],
             a[1][0] * p.x + a[1][1] * p.y + a[1][2] * p.z + a[1][3],
             a[2][0] * p.x + a[2][1] * p.y + a[2][2] * p.z + a[2][3]},
            {a[0][0] * v.x + a[0][1] * v.y + a[0][2] * v.z,
             a[1][0] * v.x + a[1][1] * v.y + a[1][2] * v.z,
             a[2][0] * v.x + a[2][1] * v.y + a[2][2] * v.z},
            ray.tmax,
            ray.time};
}
}  // namespace

bool ObjectNode::passes_bound(const Ray& ray) const {
    for (const auto& b : bounded_by_) {
        LocalHit h;
        if (!b->intersect(ray, kInfinity, false, &h) && !b->inside(ray.origin)) return false;
    }
    return true;
}

bool ObjectNode::passes_clip(const Vec3& p) const {
    for (const auto& c : clipped_by_)
        if (!c->inside(p)) return false;
    return true;
}

bool ObjectNode::moving_query(const Ray& ray, Transform* at, Ray* local) const {
    if (!motion_->at(ray.time, at)) return false;  // scaled to nothing at this time
    *local = to_local(*at, false, ray);
    return true;
}

bool ObjectNode::intersect(const Ray& ray, double tmax, bool shadow, LocalHit* hit) const {
    if (motion_) {
        Transform at;
        Ray local;
        if (!moving_query(ray, &at, &local) || !still_->intersect(local, tmax, shadow, hit))
            return false;
        transform_hit(at, hit);
        return true;
    }
    if (shadow && (flags_ & kNoShadow)) return false;
    if (!bounded_by_.empty() && !passes_bound(ray)) return false;
    if (clipped_by_.empty()) return intersect_unclipped(ray, tmax, shadow, hit);
    HitList all;
    intersect_all_unclipped(ray, tmax, &all, false);
    bool found = false;
    for (auto& h : all) {
        if (h.t >= tmax || (found && h.t >= hit->t)) continue;
        if (shadow && (h.flags & kNoShadow)) continue;
        if (!passes_clip(h.p)) continue;
        *hit = h;
        found = true;
    }
    return found;
}

bool ObjectNode::intersect_deferred(const Ray& ray, double tmax, LocalHit* hit,
                                    bool* deferred) const {
    *deferred = clipped_by_.empty() && bounded_by_.empty() && !motion_;
    if (!*deferred) return intersect(ray, tmax, false, hit);
    return intersect_local(to_local(xf_, identity_, ray), tmax, false, hit);
}

bool ObjectNode::occludes(const Ray& ray, double tmax) const {
    if (flags_ & kNoShadow) return false;
    if (motion_) {
        Transform at;
        Ray local;
        return moving_query(ray, &at, &local) && still_->occludes(local, tmax);
    }
    // A plain primitive (inverse changes only normals): the any-hit query.
    if (prim_ && clipped_by_.empty() && bounded_by_.empty())
        return prim_->occludes(to_local(xf_, identity_, ray), tmax);
    if (is_csg_ && op_ == scene::CsgOp::Union && clipped_by_.empty() && bounded_by_.empty() &&
        !child_bvh_.empty()) {
        Ray local = to_local(xf_, identity_, ray);
        double t = tmax;
        if (child_bvh_.traverse(local, t, [&](int i, double&) {
                return children_[i]->occludes(local, tmax);
            }))
            return true;
        for (int i : unbounded_children_)
            if (children_[i]->occludes(local, tmax)) return true;
        return false;
    }
    if (is_csg_ && clipped_by_.empty() && bounded_by_.empty())
        return csg_occludes(to_local(xf_, identity_, ray), tmax);
    LocalHit h;
    return intersect(ray, tmax, true, &h);
}

// The same answer as intersect(..., shadow = true) finding a hit, without its cost: no sort,
// no normals or error bounds carried through transforms, and no further child once one
// surface is kept. (A union never comes here: occludes() asks its children directly.)
bool ObjectNode::csg_occludes(const Ray& ray, double tmax) const {
    HitList hits;
    for (size_t i = 0; i < children_.size(); ++i) {
        hits.clear();
        children_[i]->intersect_all(ray, tmax, &hits, true);
        for (const LocalHit& h : hits)
            if (!(h.flags & kNoShadow) && csg_keeps(i, h.p)) return true;
    }
    return false;
}

void ObjectNode::intersect_all(const Ray& ray, double tmax, HitList* hits,
                               bool points_only) const {
    if (motion_) {
        Transform at;
        Ray local;
        if (!moving_query(ray, &at, &local)) return;
        const size_t first = hits->size();
        still_->intersect_all(local, tmax, hits, points_only);
        for (size_t i = first; i < hits->size(); ++i) {
            if (points_only)
                (*hits)[i].p = at.point((*hits)[i].p);
            else
                transform_hit(at, &(*hits)[i]);
        }
        return;
    }
    if (!bounded_by_.empty() && !passes_bound(ray)) return;
    if (clipped_by_.empty()) {
        intersect_all_unclipped(ray, tmax, hits, points_only);
        return;
    }
    size_t first = hits->size();
    intersect_all_unclipped(ray, tmax, hits, points_only);
    auto keep = std::remove_if(hits->begin() + first, hits->end(),
                               [&](const LocalHit& h) { return !passes_clip(h.p); });
    hits->truncate(static_cast<size_t>(keep - hits->begin()));
}

void ObjectNode::gradient_notes(std::vector<GradientNote>* out) const {
    if (still_) still_->gradient_notes(out);
    if (prim_) prim_->gradient_notes(out);
    for (const auto& c : children_) c->gradient_notes(out);
}

Bounds3 ObjectNode::bounds_within(const Bounds3& box) const {
    const Bounds3 b = overlap(bounds_, box);
    if (!prim_ || inverse_ || motion_ || b.empty()) return b;
    const Bounds3 local_box = identity_ ? b : xf_.inverse().bounds(b);
    const Bounds3 in = prim_->bounds_within(local_box);
    if (in.empty()) return in;
    return overlap(b, identity_ ? in : xf_.bounds(in));
}

bool ObjectNode::inside(const Vec3& p) const {
    if (motion_) return still_->inside(xf_.inverse_point(p));
    if (!passes_clip(p)) return false;
    bool in = inside_local(identity_ ? p : xf_.inverse_point(p));
    return inverse_ ? !in : in;
}

bool ObjectNode::intersect_unclipped(const Ray& ray, double tmax, bool shadow,
                                     LocalHit* hit) const {
    if (!intersect_local(to_local(xf_, identity_, ray), tmax, shadow, hit)) return false;
    finish(hit);
    return true;
}

void ObjectNode::intersect_all_unclipped(const Ray& ray, double tmax, HitList* hits,
                                         bool points_only) const {
    size_t first = hits->size();
    intersect_all_local(to_local(xf_, identity_, ray), tmax, hits, points_only);
    for (size_t i = first; i < hits->size(); ++i) {
        if (points_only)
            finish_point(&(*hits)[i]);
        else
            finish(&(*hits)[i]);
    }
}

bool ObjectNode::csg_keeps(size_t i, const Vec3& p) const {
    switch (op_) {
        case scene::CsgOp::Union:
            return true;
        case scene::CsgOp::Merge:
            for (size_t j = 0; j < children_.size(); ++j)
                if (j != i && children_[j]->inside(p)) return false;
            return true;
        case scene::CsgOp::Intersection:
            for (size_t j = 0; j < children_.size(); ++j)
                if (j != i && !children_[j]->inside(p)) return false;
            return true;
        case scene::CsgOp::Difference:
            // POV-Ray: a - b - c = a * inverse(b) * inverse(c).
            if (i != 0 && !children_[0]->inside(p)) return false;
            for (size_t j = 1; j < children_.size(); ++j)
                if (j != i && children_[j]->inside(p)) return false;
            return true;
    }
    return true;
}

bool ObjectNode::intersect_local(const Ray& ray, double tmax, bool shadow, LocalHit* hit) const {
    if (prim_) {
        // Meshes write the whole hit, and nothing on a miss: no fresh one needed.
        if (whole_hit_) return prim_->intersect(ray, tmax, hit);
        // A fresh hit: primitives fill only the geometric fields, so material and flags
        // left in *hit by an earlier (farther) sibling must not leak into this one.
        LocalHit h;
        if (!prim_->intersect(ray, tmax, &h)) return false;
        *hit = h;
        return true;
    }
    if (op_ == scene::CsgOp::Union) return union_intersect(ray, tmax, shadow, hit);
    bool found = false;
    HitList hits;
    for (size_t i = 0; i < children_.size(); ++i) {
        hits.clear();
        children_[i]->intersect_all(ray, found ? hit->t : tmax, &hits);
        std::sort(hits.begin(), hits.end(),
                  [](const LocalHit& a, const LocalHit& b) { return a.t < b.t; });
        for (auto& h : hits) {
            if (shadow && (h.flags & kNoShadow)) continue;
            if (!csg_keeps(i, h.p)) continue;
            if (op_ == scene::CsgOp::Difference && i > 0) {
                h.ng = -h.ng;
                h.n = -h.n;
            }
            *hit = h;
            found = true;
            break;
        }
    }
    return found;
}

void ObjectNode::intersect_all_local(const Ray& ray, double tmax, HitList* hits,
                                     bool points_only) const {
    if (prim_) {
        if (points_only)
            prim_->intersect_all_points(ray, tmax, hits);
        else
            prim_->intersect_all(ray, tmax, hits);
        return;
    }
    for (size_t i = 0; i < children_.size(); ++i) {
        size_t first = hits->size();
        children_[i]->intersect_all(ray, tmax, hits, points_only);
        if (op_ == scene::CsgOp::Union) continue;
        size_t w = first;
        for (size_t k = first; k < hits->size(); ++k) {
            if (!csg_keeps(i, (*hits)[k].p)) continue;
            if (w != k) (*hits)[w] = (*hits)[k];
            LocalHit& h = (*hits)[w++];
            if (op_ == scene::CsgOp::Difference && i > 0) {
                h.ng = -h.ng;
                h.n = -h.n;
            }
        }
        hits->truncate(w);
    }
}

bool ObjectNode::inside_local(const Vec3& p) const {
    if (prim_) return prim_->inside(p);
    switch (op_) {
        case scene::CsgOp::Union:
        case scene::CsgOp::Merge:
            for (const auto& c : children_)
                if (c->inside(p)) return true;
            return false;
        case scene::CsgOp::Intersection:
            for (const auto& c : children_)
                if (!c->inside(p)) return false;
            return true;
        case scene::CsgOp::Difference:
            if (!children_[0]->inside(p)) return false;
            for (size_t j = 1; j < children_.size(); ++j)
                if (children_[j]->inside(p)) return false;
            return true;
    }
    return false;
}

}  // namespace glint::render
