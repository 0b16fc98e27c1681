// build_geometry(): every top-level object (plain unions: each of their parts) becomes an
// ObjectNode; objects with finite bounds go into a SAH BVH, unbounded ones (planes, inverse
// objects) are tested one by one.
#include "render/prepare/geometry.h"

#include <climits>
#include <cmath>
#include <utility>
#include <variant>
#include <vector>

#include "render/accel/bvh.h"
#include "render/accel/wide_bvh.h"
#include "render/prepare/material_table.h"
#include "render/shapes/mesh/mesh_kernels.h"
#include "render/shapes/mesh/mesh_prim.h"
#include "render/shapes/object_node.h"

namespace glint::render {
namespace {

class SceneGeometry final : public Geometry {
public:
    // opaque: per node, whether all its surfaces are opaque (empty: not known).
    SceneGeometry(std::vector<std::unique_ptr<ObjectNode>> nodes, std::vector<int> ids,
                  std::vector<char> opaque)
        : nodes_(std::move(nodes)), ids_(std::move(ids)), opaque_(std::move(opaque)) {
        for (char o : opaque_) any_opaque_ = any_opaque_ || o;
        // Nodes come in object order, so each object's are one run.
        for (size_t i = 0; i < ids_.size(); ++i) {
            const size_t id = static_cast<size_t>(ids_[i]);
            if (id >= object_nodes_.size()) object_nodes_.resize(id + 1, {0, 0});
            if (object_nodes_[id].second == 0) object_nodes_[id].first = static_cast<int>(i);
            object_nodes_[id].second = static_cast<int>(i) + 1;
        }
        std::vector<Bounds3> boxes;
        for (size_t i = 0; i < nodes_.size(); ++i) {
            const Bounds3& b = nodes_[i]->bounds();
            bounds_.extend(b);
            boxes.push_back(b);
            if (b.is_infinite())
                unbounded_.push_back(static_cast<int>(i));
            else
                finite_bounds_.extend(b);
        }
        bvh_ = Bvh(boxes, 2, 1, kObjectNodeCost);
        // The wide walk pays where the tree is deep: sombrero's 66,049 spheres rendered in
        // 0.68 s with the four-wide tree against 0.75 s, while 1,024 spheres (0.157 s against
        // 0.150) and drums' few hundred parts were a little slower, its per-leaf call costing
        // more than the levels it saves.
        if (bvh_.nodes().size() > kWideFrom) wide_ = WideBvh(bvh_);
    }

    void gradient_notes(std::vector<GradientNote>* out) const override {
        for (const auto& n : nodes_) n->gradient_notes(out);
    }

    bool intersect(const Ray& ray, Hit* hit) const override {
        // A non-finite ray (a bug upstream) hits nothing rather than spreading NaN.
        if (!valid(ray)) return false;
        // Two hits, the best so far and the candidate, swapped rather than copied (a node
        // writes the whole hit when it reports one, ObjectNode::intersect). Each stays in its
        // object's space until it is known to be the nearest (intersect_deferred).
        LocalHit hits[2];
        LocalHit* best = &hits[0];
        LocalHit* cand = &hits[1];
        bool best_deferred = false;
        int best_i = INT_MAX;
        // Equal t: the lower object index wins, so the result does not depend on the order in
        // which the BVH visits objects.
        auto visit = [&](int i, double& tmax) {
            bool found = best_i != INT_MAX;
            double limit = found ? next_up(best->t) : tmax;
            bool deferred = false;
            if (nodes_[i]->intersect_deferred(ray, limit, cand, &deferred) &&
                (!found || cand->t < best->t || i < best_i)) {
                std::swap(best, cand);
                best_deferred = deferred;
                best_i = i;
                tmax = best->t;
            }
            return false;
        };
        double tmax = ray.tmax;
        traverse(ray, tmax, visit);
        for (int i : unbounded_) visit(i, tmax);
        if (best_i == INT_MAX) return false;
        if (best_deferred) nodes_[best_i]->finish_deferred(best);
        to_hit(*best, ids_[best_i], hit);
        return true;
    }

    bool occluded(const Ray& ray) const override {
        if (!valid(ray)) return false;
        auto visit = [&](int i, double&) { return nodes_[i]->occludes(ray, ray.tmax); };
        double tmax = ray.tmax;
        if (traverse(ray, tmax, visit)) return true;
        for (int i : unbounded_)
            if (visit(i, tmax)) return true;
        return false;
    }

    bool occluded(const Ray& ray, int* hint) const override {
        if (!valid(ray)) return false;
        const int h = *hint;
        if (h >= 0 && h < static_cast<int>(nodes_.size()) && nodes_[h]->occludes(ray, ray.tmax))
            return true;
        auto visit = [&](int i, double&) {
            if (i == h || !nodes_[i]->occludes(ray, ray.tmax)) return false;
            *hint = i;
            return true;
        };
        double tmax = ray.tmax;
        if (traverse(ray, tmax, visit)) return true;
        for (int i : unbounded_)
            if (visit(i, tmax)) return true;
        return false;
    }

    Blocker shadow_blocker(const Ray& ray, int* hint) const override {
        if (!occluded(ray, hint)) return Blocker::None;
        if (!any_opaque_) return Blocker::Other;
        // The object found is usually the answer (and the shadow cache's next guess).
        if (opaque_[*hint]) return Blocker::Opaque;
        int h = -1;
        return occluded_by_opaque(ray, &h) ? Blocker::Opaque : Blocker::Other;
    }

    // Any hit among the opaque objects.
    bool occluded_by_opaque(const Ray& ray, int* hint) const {
        const int h = *hint;
        if (h >= 0 && h < static_cast<int>(nodes_.size()) && opaque_[h] &&
            nodes_[h]->occludes(ray, ray.tmax))
            return true;
        auto visit = [&](int i, double&) {
            if (i == h || !opaque_[i] || !nodes_[i]->occludes(ray, ray.tmax)) return false;
            *hint = i;
            return true;
        };
        double tmax = ray.tmax;
        if (traverse(ray, tmax, visit)) return true;
        for (int i : unbounded_)
            if (visit(i, tmax)) return true;
        return false;
    }

    bool intersect_object(const Ray& ray, int object, Hit* hit) const override {
        if (!valid(ray) || object < 0 || static_cast<size_t>(object) >= object_nodes_.size())
            return false;
        LocalHit hits[2];
        LocalHit* best = &hits[0];
        LocalHit* cand = &hits[1];
        bool best_deferred = false;
        int best_i = -1;
        double limit = ray.tmax;
        const auto [first, end] = object_nodes_[static_cast<size_t>(object)];
        for (int i = first; i < end; ++i) {
            bool deferred = false;
            if (nodes_[i]->intersect_deferred(ray, limit, cand, &deferred) &&
                (best_i < 0 || cand->t < best->t)) {
                std::swap(best, cand);
                best_deferred = deferred;
                best_i = i;
                limit = next_up(best->t);
            }
        }
        if (best_i < 0) return false;
        if (best_deferred) nodes_[best_i]->finish_deferred(best);
        to_hit(*best, object, hit);
        return true;
    }

    Bounds3 bounds() const override { return bounds_; }
    Bounds3 finite_bounds() const override { return finite_bounds_; }

private:
    static bool valid(const Ray& ray) {
        return is_finite(ray.origin) && is_finite(ray.dir) && !std::isnan(ray.tmax) &&
               length_squared(ray.dir) > 0;
    }

    static void to_hit(const LocalHit& h, int id, Hit* hit) {
        hit->t = h.t;
        hit->p = h.p;
        hit->p_error = h.p_error;
        hit->ng = h.ng;
        hit->n = h.n;
        hit->uv = h.uv_source ? h.uv_source->uv_at(h.uv_point) : h.uv;
        hit->has_uv = h.has_uv;
        hit->dpdu = h.dpdu;
        hit->dpdv = h.dpdv;
        hit->material = h.material;
        hit->flags = h.flags;
        hit->attributes = h.attributes;
        hit->object = id;
        hit->blend_source = h.uv_source;
        hit->blend_point = h.uv_point;
    }

    std::vector<std::unique_ptr<ObjectNode>> nodes_;
    std::vector<int> ids_;  // scene object index of each node
    std::vector<std::pair<int, int>> object_nodes_;  // per scene object: its nodes [first, end)
    std::vector<char> opaque_;  // per node: no surface of it lets light through
    bool any_opaque_ = false;
    std::vector<int> unbounded_;
    static constexpr size_t kWideFrom = 8192;  // binary nodes
    // A box test's cost against one object's (a virtual call into its own shape or mesh BVH,
    // hundreds of instructions against tens), for the SAH: at 1, a few objects that fill their
    // common box (the walls of a room) stayed one leaf, and every ray from inside the room
    // tested them all.
    static constexpr double kObjectNodeCost = 0.1;

    // The walk over the objects' BVH: visit(i, tmax) for every object whose box the ray enters
    // within tmax, nearest box first (in big scenes the eight-wide tree, through the mesh
    // kernels' SIMD box test); true when visit said so (Bvh::traverse's contract).
    template <class Visit>
    bool traverse(const Ray& ray, double& tmax, Visit& visit) const {
        if (wide_.nodes().empty()) return bvh_.traverse(ray, tmax, visit);
        struct Ctx {
            const std::vector<int>* order;
            Visit* visit;
        } ctx{&bvh_.order(), &visit};
        return kernels_.walk(
            wide_.nodes().data(), static_cast<int>(bvh_.order().size()), wide_.reach(), ray,
            &tmax,
            [](void* c, int first, int n, double* t) {
                auto* x = static_cast<Ctx*>(c);
                for (int k = first; k < first + n; ++k)
                    if ((*x->visit)((*x->order)[static_cast<size_t>(k)], *t)) return true;
                return false;
            },
            &ctx);
    }

    Bvh bvh_;
    WideBvh wide_;  // empty below kWideFrom
    const MeshKernels& kernels_ = mesh_kernels();
    Bounds3 bounds_;
    Bounds3 finite_bounds_;
};

// A plain union (no inverse, clipping or bounding) is only a group: its parts can join the
// scene's BVH directly, each with the union's transform, material and flags folded in, so a
// ray pays no nested traversal or transform for it (an OBJ placed by obj_file is such a
// union). Results are unchanged: the nearest part is found either way, ties still go to the
// earlier part, and hits keep the union's scene object index.
bool is_plain_union(const scene::Object& o) {
    const auto* csg = std::get_if<scene::Csg>(&o.shape);
    return csg && csg->op == scene::CsgOp::Union && !o.inverse && o.clipped_by.empty() &&
           o.bounded_by.empty();
}

void flatten(const scene::Object& o, std::vector<scene::Object>* out) {
    if (!is_plain_union(o)) {
        out->push_back(o);
        return;
    }
    for (const scene::Object& child : std::get<scene::Csg>(o.shape).children) {
        scene::Object part = child;
        part.transform = child.transform.then(o.transform);
        for (auto* extra : {&part.bounded_by, &part.clipped_by})
            for (scene::Object& e : *extra) e.transform = e.transform.then(o.transform);
        if (part.material < 0) part.material = o.material;
        part.no_shadow = part.no_shadow || o.no_shadow;
        part.no_image = part.no_image || o.no_image;
        part.no_reflection = part.no_reflection || o.no_reflection;
        part.no_radiosity = part.no_radiosity || o.no_radiosity;
        part.double_illuminate = part.double_illuminate || o.double_illuminate;
        part.no_global_lights = part.no_global_lights || o.no_global_lights;
        part.hollow = part.hollow || o.hollow;
        if (part.light_group < 0) part.light_group = o.light_group;
        flatten(part, out);
    }
}

// Parts that can share one mesh primitive with their neighbours: a mesh (without the
// inside_vector that CSG asks) and nothing else about the object that makes it differ.
bool mergeable_mesh(const scene::Object& o, const scene::Scene& scene) {
    const auto* ref = std::get_if<scene::MeshRef>(&o.shape);
    return ref && ref->mesh >= 0 && ref->mesh < static_cast<int>(scene.meshes.size()) &&
           !scene.meshes[ref->mesh].has_inside_vector && !o.inverse && o.clipped_by.empty() &&
           o.bounded_by.empty() && o.motion.empty() &&
           scene.meshes[ref->mesh].motion_positions.empty();
}

// Whether every surface of `o` has an opaque material: its own or the one it inherits, its CSG
// children's, its mesh faces', its blob components'. A surface without a material counts as
// opaque, as in the shadow walk. (clipped_by and bounded_by shapes show no surface.)
bool all_opaque(const scene::Object& o, int inherited, const scene::Scene& scene,
                const MaterialTable& materials) {
    const int m = o.material >= 0 ? o.material : inherited;
    auto ok = [&](int id) { return materials.opaque(id); };
    if (const auto* csg = std::get_if<scene::Csg>(&o.shape)) {
        for (const scene::Object& c : csg->children)
            if (!all_opaque(c, m, scene, materials)) return false;
        return true;
    }
    if (const auto* ref = std::get_if<scene::MeshRef>(&o.shape)) {
        if (ref->mesh >= 0 && ref->mesh < static_cast<int>(scene.meshes.size()))
            for (const scene::MeshFace& f : scene.meshes[ref->mesh].faces)
                if (!ok(f.material >= 0 ? f.material : m)) return false;
    }
    if (const auto* blob = std::get_if<scene::Blob>(&o.shape))
        for (const scene::BlobComponent& c : blob->components)
            if (c.material >= 0 && !ok(c.material)) return false;
    return ok(m);
}

bool same_frame(const scene::Object& a, const scene::Object& b) {
    return a.transform.matrix() == b.transform.matrix() &&
           a.transform.inverse_matrix() == b.transform.inverse_matrix() &&
           a.no_shadow == b.no_shadow && a.no_image == b.no_image &&
           a.no_reflection == b.no_reflection && a.double_illuminate == b.double_illuminate &&
           a.no_radiosity == b.no_radiosity && a.no_global_lights == b.no_global_lights &&
           a.light_group == b.light_group && a.hollow == b.hollow;
}

// One mesh primitive for parts[first, end) (all mergeable_mesh, one frame), as a node with
// their transform and flags.
std::unique_ptr<ObjectNode> merged_node(const std::vector<scene::Object>& parts, size_t first,
                                        size_t end, const scene::Scene& scene,
                                        Diagnostics& diag) {
    std::vector<MeshPart> meshes;
    for (size_t j = first; j < end; ++j)
        meshes.push_back(
            {&scene.meshes[std::get<scene::MeshRef>(parts[j].shape).mesh], parts[j].material});
    const bool baked = bake_exact(parts[first].transform);
    scene::Object like = parts[first];
    like.material = -1;  // each face has its part's
    return ObjectNode::wrap(
        make_merged_mesh(meshes, diag, baked ? &parts[first].transform : nullptr), like, baked);
}

}  // namespace

std::unique_ptr<Geometry> build_geometry(const scene::Scene& scene,
                                         const scene::Features& features, Diagnostics& diag) {
    return build_geometry(scene, features, MaterialTable(scene, nullptr), diag);
}

std::unique_ptr<Geometry> build_geometry(const scene::Scene& scene,
                                         const scene::Features& features,
                                         const MaterialTable& materials, Diagnostics& diag) {
    std::vector<std::unique_ptr<ObjectNode>> nodes;
    std::vector<int> ids;
    // Which nodes are opaque all over, for the shadow walk (only scenes with transparency walk).
    std::vector<char> node_opaque;
    // Keeps a node of scene object `id`, made of the `count` objects at objs.
    auto push = [&](std::unique_ptr<ObjectNode> node, int id, const scene::Object* objs,
                    size_t count) {
        if (!node || node->bounds().empty()) return;
        nodes.push_back(std::move(node));
        ids.push_back(id);
        if (!features.transparency) return;
        bool all = true;
        for (size_t j = 0; j < count; ++j)
            all = all && all_opaque(objs[j], -1, scene, materials);
        node_opaque.push_back(all);
    };
    SharedMeshes shared;  // objects instancing one mesh share its primitive
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const scene::Object& o = scene.objects[i];
        const int id = static_cast<int>(i);
        if (!is_plain_union(o)) {
            push(ObjectNode::build(o, scene, diag, &shared), id, &o, 1);
            continue;
        }
        std::vector<scene::Object> parts;
        flatten(o, &parts);
        // Runs of meshes with one transform (an OBJ's groups) become one primitive; the order
        // of the parts, and so every tie, is kept.
        for (size_t k = 0; k < parts.size();) {
            size_t end = k + 1;
            if (mergeable_mesh(parts[k], scene))
                while (end < parts.size() && mergeable_mesh(parts[end], scene) &&
                       same_frame(parts[k], parts[end]))
                    ++end;
            push(end - k == 1 ? ObjectNode::build(parts[k], scene, diag)
                              : merged_node(parts, k, end, scene, diag),
                 id, &parts[k], end - k);
            k = end;
        }
    }
    return std::make_unique<SceneGeometry>(std::move(nodes), std::move(ids),
                                           std::move(node_opaque));
}

}  // namespace glint::render
