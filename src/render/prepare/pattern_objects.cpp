#include "render/prepare/pattern_objects.h"

#include "render/shapes/object_node.h"

namespace glint::render {
namespace {

class BuiltPatternObjects final : public PatternObjects {
public:
    explicit BuiltPatternObjects(std::vector<std::unique_ptr<ObjectNode>> nodes)
        : nodes_(std::move(nodes)) {}
    bool inside(int object, const Vec3& p) const override {
        if (object < 0 || static_cast<size_t>(object) >= nodes_.size()) return false;
        const ObjectNode* n = nodes_[static_cast<size_t>(object)].get();
        return n && n->inside(p);
    }

private:
    std::vector<std::unique_ptr<ObjectNode>> nodes_;  // null where the object was unusable
};

}  // namespace

std::unique_ptr<PatternObjects> build_pattern_objects(const scene::Scene& scene,
                                                      Diagnostics& diag) {
    if (scene.pattern_objects.empty()) return nullptr;
    std::vector<std::unique_ptr<ObjectNode>> nodes;
    for (const scene::Object& o : scene.pattern_objects)
        nodes.push_back(ObjectNode::build(o, scene, diag));
    return std::make_unique<BuiltPatternObjects>(std::move(nodes));
}

}  // namespace glint::render
