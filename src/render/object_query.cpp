#include "render/render.h"

#include "render/geometry.h"
#include "render/textures/pigment.h"
#include "scene/features.h"

namespace glint::render {

bool answer_object_query(const scene::Scene& one, int kind, const Vec3& a, const Vec3& b, Vec3& lo,
                         Vec3& hi) {
    if (one.objects.empty()) return false;
    Diagnostics quiet;  // the scene's own parse reports problems with the object
    std::unique_ptr<Geometry> g = build_geometry(one, scene::analyze(one), quiet);
    if (kind == 0) {
        Bounds3 box = g->bounds();
        if (box.empty()) return false;
        lo = box.lo;
        hi = box.hi;
        return true;
    }
    Ray ray{a, normalize(b), kInfinity};
    Hit hit;
    if (!g->intersect(ray, &hit)) return false;
    lo = hit.p;
    // POV-Ray's trace returns the object's normal at the hit, oriented by the object (not
    // flipped toward the ray).
    hi = hit.n;
    return true;
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
