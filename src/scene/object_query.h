// What the scene language asks about one object while the scene is parsed: POV-Ray's trace(),
// inside() and min_extent()/max_extent(). An importer cannot see the renderer, so the
// application hands it a function that prepares an object with the renderer's geometry
// (render::prepare_object_query); the importer prepares each declared object once and asks it
// as often as the scene does (a #while loop of trace() calls pays for one build).
#pragma once

#include <functional>
#include <memory>

#include "core/math.h"
#include "scene/scene.h"

namespace glint::scene {

struct ObjectAnswer {
    bool found = false;  // bounds(): bounded and not empty; trace(): the ray hit the object
    Vec3 lo, hi;         // bounds(): the world bounding box
    Vec3 point, normal;  // trace(): the hit, and the object's normal there (as POV-Ray's trace
                         // gives it: oriented by the object, not flipped toward the ray)
};

class PreparedObject {
public:
    virtual ~PreparedObject() = default;
    virtual ObjectAnswer bounds() const = 0;
    // The first hit along the ray from `origin` along `direction` (any non-zero length).
    virtual ObjectAnswer trace(const Vec3& origin, const Vec3& direction) const = 0;
    // POV-Ray's Inside_Object: whether p lies inside the (solid) object.
    virtual bool inside(const Vec3& p) const = 0;
};

// `one` is a scene holding only the object.
using ObjectPrepareFn = std::function<std::shared_ptr<const PreparedObject>(const Scene& one)>;

}  // namespace glint::scene
