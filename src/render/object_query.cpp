#include "render/render.h"

#include "render/prepare/geometry.h"
#include "render/textures/pigment.h"
#include "scene/features.h"

namespace glint::render {

scene::ObjectAnswer answer_object_query(const scene::Scene& one, scene::ObjectQuery query,
                                        const Vec3& origin, const Vec3& direction) {
    scene::ObjectAnswer answer;
    if (one.objects.empty()) return answer;
    Diagnostics quiet;  // the scene's own parse reports problems with the object
    std::unique_ptr<Geometry> g = build_geometry(one, scene::analyze(one), quiet);
    if (query == scene::ObjectQuery::Bounds) {
        Bounds3 box = g->bounds();
        if (box.empty()) return answer;
        answer.found = true;
        answer.lo = box.lo;
        answer.hi = box.hi;
        return answer;
    }
    Ray ray{origin, normalize(direction), kInfinity};
    Hit hit;
    if (!g->intersect(ray, &hit)) return answer;
    answer.found = true;
    answer.point = hit.p;
    answer.normal = hit.n;
    return answer;
}

void parse_time_pattern(const void*, const scene::Function& f, const Vec3& p, double out[5]) {
    for (int k = 0; k < 5; ++k) out[k] = 0;
    if (f.pigment.empty()) return;
    const scene::Pigment& pg = f.pigment[0];
    if (f.kind == scene::FunctionKind::Pattern) {
        out[0] = evaluate_pattern(pg.kind, pg.params, pg.transform.inverse_point(p), {});
        return;
    }
    scene::ColorFT c;
    PigmentEvaluator(nullptr).evaluate(pg, {p, {}, false}, &c);
    out[0] = c.rgb.r;
    out[1] = c.rgb.g;
    out[2] = c.rgb.b;
    out[3] = c.filter;
    out[4] = c.transmit;
}

}  // namespace glint::render
