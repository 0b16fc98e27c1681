// A transform that changes over the shutter (motion blur): matrices at evenly spaced times in
// [0, 1], interpolated as Cycles 3.4 interpolates object and camera motion
// (util/transform.h transform_motion_array_interpolate): each step decomposed into translation,
// rotation (a unit quaternion) and a 3x3 scale/shear, translation and scale blended linearly,
// rotation by slerp. Used by moving objects (render/shapes/object_node.h) and the camera's
// shutter (render/film/shutter.h).
#pragma once

#include <vector>

#include "core/transform.h"

namespace glint {

// M = translate(translation) * rotation(q) * scale, scale a general 3x3 (shear included).
struct DecomposedTransform {
    Vec3 translation{0, 0, 0};
    double q[4] = {1, 0, 0, 0};  // w, x, y, z
    double scale[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
};

// The polar decomposition of m's linear part (Higham's iteration R <- (R + R^-T) / 2), the
// rotation made proper by negating it when the determinant is negative (the scale then takes
// the sign), as Cycles' transform_decompose does.
DecomposedTransform decompose(const Matrix4& m);
Matrix4 compose(const DecomposedTransform& d);

class MotionTransform {
public:
    // `steps`: object (or camera) to world at times i / (n - 1), n >= 2. Consecutive
    // quaternions are given the same hemisphere (the shorter way round), and a step scaled to
    // nothing borrows its neighbour's rotation, as in Cycles' transform_motion_decompose.
    explicit MotionTransform(const std::vector<Matrix4>& steps);

    size_t steps() const { return steps_.size(); }
    // The transform at `time` in [0, 1] (clamped).
    Matrix4 matrix_at(double time) const;
    // With its inverse; false where it has none (scaled to nothing at that time).
    bool at(double time, Transform* out) const;
    // A box that holds every point of `local` at every time in [0, 1]: boxes at sampled times
    // padded by how far a point can travel between samples (translation, rotation and scale
    // rates bound the speed), so it is conservative also for rotations.
    Bounds3 bounds(const Bounds3& local) const;

private:
    std::vector<DecomposedTransform> steps_;
};

}  // namespace glint
