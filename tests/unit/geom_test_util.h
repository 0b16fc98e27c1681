// Helpers for the geometry tests: one-object scenes and hit queries through build_geometry().
#pragma once

#include <memory>

#include "render/geometry.h"
#include "scene/features.h"
#include "scene/scene.h"

namespace glint::test {

inline scene::Object object(scene::Shape shape, Transform xf = {}, int material = 0) {
    scene::Object o;
    o.shape = std::move(shape);
    o.transform = xf;
    o.material = material;
    return o;
}

inline scene::Scene scene_of(std::vector<scene::Object> objects) {
    scene::Scene s;
    s.materials.resize(4);
    s.objects = std::move(objects);
    return s;
}

inline std::unique_ptr<render::Geometry> build(const scene::Scene& s) {
    Diagnostics diag;
    return render::build_geometry(s, scene::analyze(s), diag);
}

inline std::unique_ptr<render::Geometry> build_one(scene::Shape shape, Transform xf = {}) {
    return build(scene_of({object(std::move(shape), xf)}));
}

inline render::Ray ray(Vec3 o, Vec3 d, double tmax = kInfinity) { return {o, d, tmax}; }

}  // namespace glint::test
