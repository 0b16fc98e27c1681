#include "render/object_query.h"

#include "render/geometry.h"
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

}  // namespace glint::render
