#include "render/film/shutter.h"

namespace glint::render {

Shutter::Shutter(const scene::Scene& scene) {
    for (const scene::Object& o : scene.objects) active_ = active_ || !o.motion.empty();
    for (const scene::Mesh& m : scene.meshes) active_ = active_ || !m.motion_positions.empty();
    const scene::Camera& c = scene.camera;
    if (c.motion.size() >= 2 && c.centre.inverse(&centre_inverse_)) {
        camera_ = std::make_shared<const MotionTransform>(c.motion);
        active_ = true;
    }
}

void Shutter::expose(double time, Ray* ray) const {
    ray->time = time;
    if (!camera_) return;
    // World at the frame -> camera -> world at `time`.
    const Transform moved(camera_->matrix_at(time) * centre_inverse_, Matrix4{});
    ray->origin = moved.point(ray->origin);
    ray->dir = normalize(moved.vector(ray->dir));
}

}  // namespace glint::render
