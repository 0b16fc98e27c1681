// Motion blur's shutter: the time in [0, 1] each camera ray is given (0 the shutter opening,
// 1 its closing, 0.5 the frame) and the camera's own motion at that time. The tile driver
// asks it once per camera sample; rays keep their time along the whole path, so moving
// objects (render/shapes/object_node.h) are met where they are at that time. A scene without
// motion has an inactive shutter: its rays keep 0.5 and the driver draws nothing more.
#pragma once

#include <memory>

#include "core/motion.h"
#include "render/ray.h"
#include "scene/scene.h"

namespace glint::render {

class Shutter {
public:
    Shutter() = default;
    // Active when the camera, any object or any mesh has motion (scene::Camera::motion,
    // scene::Object::motion, scene::Mesh::motion_positions).
    explicit Shutter(const scene::Scene& scene);

    bool active() const { return active_; }
    // The shutter time for a uniform `u` in [0, 1): Cycles' default shutter curve, a box,
    // opens and closes at once, so the time is uniform over the shutter.
    static double time(double u) { return u; }
    // `ray`, made by the camera at the frame, as the camera at `time` makes it (its matrix
    // interpolated as an object's), and given that time.
    void expose(double time, Ray* ray) const;

private:
    bool active_ = false;
    std::shared_ptr<const MotionTransform> camera_;  // null: the camera stays put
    Matrix4 centre_inverse_;                         // world -> camera at the frame
};

}  // namespace glint::render
