#include "render/prepare/containing.h"

#include <algorithm>
#include <utility>
#include <variant>

#include "core/float.h"

namespace glint::render {

std::vector<Containing> objects_containing_camera(const scene::Scene& scene,
                                                  const Geometry& geometry) {
    const scene::CameraKind k = scene.camera.kind;
    if (k == scene::CameraKind::Orthographic || k == scene::CameraKind::Cylinder3 ||
        k == scene::CameraKind::Cylinder4)
        return {};
    return objects_containing(scene, geometry, scene.camera.location, scene.camera.direction);
}

std::vector<Containing> objects_containing(const scene::Scene& scene, const Geometry& geometry,
                                           const Vec3& p, const Vec3& dir) {
    std::vector<Containing> inside;
    // Walk a ray from the point: an object whose first crossing leaves it (the normal, which
    // points out of the solid, along the ray) contains the point.
    Ray r;
    r.origin = p;
    r.dir = normalize(dir);
    auto split_union = [&](int object) {
        if (object < 0 || object >= static_cast<int>(scene.objects.size())) return false;
        const scene::Object& o = scene.objects[static_cast<size_t>(object)];
        const auto* csg = std::get_if<scene::Csg>(&o.shape);
        return csg && csg->op == scene::CsgOp::Union && o.clipped_by.empty() &&
               o.bounded_by.empty();
    };
    std::vector<std::pair<int, int>> seen;  // (object, material or -1)
    for (int i = 0; i < 256; ++i) {
        Hit hit;
        if (!geometry.intersect(r, &hit)) break;
        const std::pair<int, int> key{hit.object, split_union(hit.object) ? hit.material : -1};
        if (std::find(seen.begin(), seen.end(), key) == seen.end()) {
            seen.push_back(key);
            if (dot(hit.ng, r.dir) > 0.0 && hit.material >= 0)
                inside.push_back({hit.object, hit.material, (hit.flags & kHollow) != 0});
        }
        r.origin = offset_ray_origin(hit.p, hit.p_error, hit.ng, r.dir);
    }
    std::stable_sort(inside.begin(), inside.end(),
                     [](const Containing& a, const Containing& b) { return a.object < b.object; });
    return inside;
}

}  // namespace glint::render
