// Helpers for the geometry tests: one-object scenes and hit queries through build_geometry().
#pragma once

#include <algorithm>
#include <memory>
#include <vector>

#include "core/log.h"
#include "render/prepare/geometry.h"
#include "render/shapes/object_node.h"
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

// scene_of({o}) without the initializer_list (see build_one).
inline scene::Scene scene_with(scene::Object o) {
    std::vector<scene::Object> objects;
    objects.push_back(std::move(o));
    return scene_of(std::move(objects));
}

inline std::unique_ptr<render::Geometry> build_one(scene::Shape shape, Transform xf = {}) {
    // Not scene_of({...}): copying an Object out of an initializer_list trips GCC 12's
    // -Wmaybe-uninitialized false positive on the Shape variant at -O3.
    std::vector<scene::Object> objects;
    objects.push_back(object(std::move(shape), xf));
    return build(scene_of(std::move(objects)));
}

// A closed cube of 12 triangles with corners `lo` and `lo + 1`.
inline scene::Mesh unit_cube_mesh(Vec3 lo = {}) {
    scene::Mesh m;
    for (int i = 0; i < 8; ++i)
        m.positions.push_back(lo + Vec3(double(i & 1), double(i >> 1 & 1), double(i >> 2 & 1)));
    const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                             {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& q : quads) {
        scene::MeshFace a, b;
        a.v = {q[0], q[1], q[2]};
        b.v = {q[0], q[2], q[3]};
        m.faces.push_back(a);
        m.faces.push_back(b);
    }
    return m;
}

inline render::Ray ray(Vec3 o, Vec3 d, double tmax = kInfinity) { return {o, d, tmax}; }

// The object tree of one shape in an otherwise empty scene (null where it cannot be built).
inline std::unique_ptr<render::ObjectNode> node_of(const scene::Shape& s, Transform xf = {}) {
    const scene::Scene sc = scene_of({});
    Diagnostics diag;
    return render::ObjectNode::build(object(s, xf), sc, diag);
}

// POV-Ray's Inside through the object tree.
inline bool inside(const scene::Shape& s, const Vec3& p) {
    auto node = node_of(s);
    return node && node->inside(p);
}

// Every hit depth along a ray (intersect_all), sorted.
inline std::vector<double> hit_depths(const render::ObjectNode& node, const render::Ray& r) {
    render::HitList hits;
    node.intersect_all(r, kInfinity, &hits);
    std::vector<double> t;
    for (const auto& h : hits) t.push_back(h.t);
    std::sort(t.begin(), t.end());
    return t;
}
inline std::vector<double> hit_depths(const scene::Shape& s, const render::Ray& r) {
    return hit_depths(*node_of(s), r);
}

}  // namespace glint::test
