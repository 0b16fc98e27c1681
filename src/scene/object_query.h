// What the scene language asks about one object while the scene is parsed: POV-Ray's trace()
// and min_extent()/max_extent(). An importer cannot see the renderer, so the application hands
// it the renderer's answer (render::answer_object_query) as an ObjectQueryFn.
#pragma once

#include <functional>

#include "core/math.h"
#include "scene/scene.h"

namespace glint::scene {

enum class ObjectQuery {
    Bounds,  // min_extent()/max_extent(): the object's world bounding box
    Trace,   // trace(): the first hit along a ray
};

struct ObjectAnswer {
    bool found = false;  // Bounds: bounded and not empty; Trace: the ray hit the object
    Vec3 lo, hi;         // Bounds: the world bounding box
    Vec3 point, normal;  // Trace: the hit, and the object's normal there (as POV-Ray's trace
                         // gives it: oriented by the object, not flipped toward the ray)
};

// `one` is a scene holding only the object; origin and direction are Trace's ray (any length).
using ObjectQueryFn = std::function<ObjectAnswer(const Scene& one, ObjectQuery query,
                                                 const Vec3& origin, const Vec3& direction)>;

}  // namespace glint::scene
