#include "render/render.h"

#include "render/prepare/geometry.h"
#include "render/shapes/object_node.h"
#include "render/textures/pigment.h"
#include "scene/features.h"

namespace glint::render {

namespace {

class PreparedQueryObject final : public scene::PreparedObject {
public:
    explicit PreparedQueryObject(const scene::Scene& one) {
        if (one.objects.empty()) return;
        Diagnostics quiet;  // the scene's own parse reports problems with the object
        geometry_ = build_geometry(one, scene::analyze(one), quiet);
        node_ = ObjectNode::build(one.objects[0], one, quiet);
    }

    scene::ObjectAnswer bounds() const override {
        scene::ObjectAnswer answer;
        if (!geometry_) return answer;
        Bounds3 box = geometry_->bounds();
        if (box.empty()) return answer;
        answer.found = true;
        answer.lo = box.lo;
        answer.hi = box.hi;
        return answer;
    }

    scene::ObjectAnswer trace(const Vec3& origin, const Vec3& direction) const override {
        scene::ObjectAnswer answer;
        if (!geometry_) return answer;
        Ray ray{origin, normalize(direction), kInfinity};
        Hit hit;
        if (!geometry_->intersect(ray, &hit)) return answer;
        answer.found = true;
        answer.point = hit.p;
        answer.normal = hit.n;
        return answer;
    }

    bool inside(const Vec3& p) const override { return node_ && node_->inside(p); }

private:
    std::unique_ptr<Geometry> geometry_;
    std::unique_ptr<ObjectNode> node_;
};

}  // namespace

std::shared_ptr<const scene::PreparedObject> prepare_object_query(const scene::Scene& one) {
    return std::make_shared<PreparedQueryObject>(one);
}

void parse_time_pattern(const void* user, const scene::Function& f, const Vec3& p,
                        double out[5]) {
    for (int k = 0; k < 5; ++k) out[k] = 0;
    if (f.pigment.empty()) return;
    PatternContext ctx;
    if (const auto* env = static_cast<const scene::FunctionEnv*>(user)) {
        ctx.noise_generator = env->noise_generator;
        ctx.functions = env->functions;
    }
    const scene::Pigment& pg = f.pigment[0];
    if (f.kind == scene::FunctionKind::Pattern) {
        out[0] = evaluate_pattern(pg.kind, pg.params, pg.transform.inverse_point(p), ctx);
        return;
    }
    scene::ColorFT c;
    PigmentEvaluator(nullptr, ctx).evaluate(pg, {p, {}, false}, &c);
    out[0] = c.rgb.r;
    out[1] = c.rgb.g;
    out[2] = c.rgb.b;
    out[3] = c.filter;
    out[4] = c.transmit;
}

}  // namespace glint::render
