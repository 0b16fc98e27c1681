#include "render/prepare/containing.h"

#include <algorithm>

#include "core/float.h"

namespace glint::render {

std::vector<Containing> objects_containing_camera(const scene::Scene& scene,
                                                  const Geometry& geometry) {
    const scene::CameraKind k = scene.camera.kind;
    if (k == scene::CameraKind::Orthographic || k == scene::CameraKind::Cylinder3 ||
        k == scene::CameraKind::Cylinder4)
        return {};
    return objects_containing(geometry, scene.camera.location, scene.camera.direction);
}

std::vector<Containing> objects_containing(const Geometry& geometry, const Vec3& p,
                                           const Vec3& dir) {
    std::vector<Containing> inside;
    // Walk a ray from the point: an object whose first crossing leaves it (the normal, which
    // points out of the solid, along the ray) contains the point.
    Ray r;
    r.origin = p;
    r.dir = normalize(dir);
    std::vector<int> seen;
    for (int i = 0; i < 256; ++i) {
        Hit hit;
        if (!geometry.intersect(r, &hit)) break;
        if (std::find(seen.begin(), seen.end(), hit.object) == seen.end()) {
            seen.push_back(hit.object);
            if (dot(hit.ng, r.dir) > 0.0 && hit.material >= 0)
                inside.push_back({hit.object, hit.material, (hit.flags & kHollow) != 0});
        }
        r.origin = offset_ray_origin(hit.p, hit.p_error, hit.ng, r.dir);
    }
    std::sort(inside.begin(), inside.end(),
              [](const Containing& a, const Containing& b) { return a.object < b.object; });
    return inside;
}

}  // namespace glint::render
