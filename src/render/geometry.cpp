// build_geometry(): every top-level object becomes an ObjectNode; objects with finite bounds go
// into a SAH BVH, unbounded ones (planes, inverse objects) are tested one by one.
#include "render/geometry.h"

#include <vector>

#include "render/shapes/object_node.h"

namespace glint::render {
namespace {

class SceneGeometry final : public Geometry {
public:
    SceneGeometry(std::vector<std::unique_ptr<ObjectNode>> nodes, std::vector<int> ids)
        : nodes_(std::move(nodes)), ids_(std::move(ids)) {
        for (const auto& n : nodes_) bounds_.extend(n->bounds());
    }

    bool intersect(const Ray& ray, Hit* hit) const override {
        LocalHit best;
        int best_id = -1;
        for (size_t i = 0; i < nodes_.size(); ++i) {
            LocalHit h;
            double tmax = best_id < 0 ? ray.tmax : best.t;
            if (nodes_[i]->intersect(ray, tmax, false, &h)) {
                best = h;
                best_id = ids_[i];
            }
        }
        if (best_id < 0) return false;
        to_hit(best, best_id, hit);
        return true;
    }

    bool occluded(const Ray& ray) const override {
        for (const auto& n : nodes_) {
            LocalHit h;
            if (n->intersect(ray, ray.tmax, true, &h)) return true;
        }
        return false;
    }

    Bounds3 bounds() const override { return bounds_; }

private:
    static void to_hit(const LocalHit& h, int id, Hit* hit) {
        hit->t = h.t;
        hit->p = h.p;
        hit->p_error = h.p_error;
        hit->ng = h.ng;
        hit->n = h.n;
        hit->uv = h.uv;
        hit->has_uv = h.has_uv;
        hit->material = h.material;
        hit->flags = h.flags;
        hit->object = id;
    }

    std::vector<std::unique_ptr<ObjectNode>> nodes_;
    std::vector<int> ids_;
    Bounds3 bounds_;
};

}  // namespace

std::unique_ptr<Geometry> build_geometry(const scene::Scene& scene, const scene::Features&,
                                         Diagnostics& diag) {
    std::vector<std::unique_ptr<ObjectNode>> nodes;
    std::vector<int> ids;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        auto node = ObjectNode::build(scene.objects[i], scene, diag);
        if (!node || node->bounds().empty()) continue;
        nodes.push_back(std::move(node));
        ids.push_back(static_cast<int>(i));
    }
    return std::make_unique<SceneGeometry>(std::move(nodes), std::move(ids));
}

}  // namespace glint::render
