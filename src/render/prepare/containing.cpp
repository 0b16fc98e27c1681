#include "render/prepare/containing.h"

#include <algorithm>

#include "core/float.h"

namespace glint::render {

std::vector<Containing> objects_containing_camera(const scene::Scene& scene,
                                                  const Geometry& geometry) {
    std::vector<Containing> inside;
    const scene::CameraKind k = scene.camera.kind;
    if (k == scene::CameraKind::Orthographic || k == scene::CameraKind::Cylinder3 ||
        k == scene::CameraKind::Cylinder4)
        return inside;
    // Walk a ray from the eye: an object whose first crossing leaves it (the normal, which
    // points out of the solid, along the ray) contains the eye.
    Ray r;
    r.origin = scene.camera.location;
    r.dir = normalize(scene.camera.direction);
    std::vector<int> seen;
    for (int i = 0; i < 256; ++i) {
        Hit hit;
        if (!geometry.intersect(r, &hit)) break;
        if (std::find(seen.begin(), seen.end(), hit.object) == seen.end()) {
            seen.push_back(hit.object);
            if (dot(hit.ng, r.dir) > 0.0 && hit.material >= 0)
                inside.push_back({hit.object, hit.material});
        }
        r.origin = offset_ray_origin(hit.p, hit.p_error, hit.ng, r.dir);
    }
    std::sort(inside.begin(), inside.end(),
              [](const Containing& a, const Containing& b) { return a.object < b.object; });
    return inside;
}

}  // namespace glint::render
