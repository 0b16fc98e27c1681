// Blender's VECTOR shader nodes Mapping and Vector Rotate as pure functions giving Cycles
// 3.4's values (intern/cycles/kernel/svm/mapping_util.h, vector_rotate.h; util/transform.h),
// in single precision. Enums are named after Blender's Python enum identifiers; each has a
// parse_* function taking that identifier. (Vector Math is in converter_nodes.h, Vector Curves
// in color_nodes.h.)
#pragma once

#include <string_view>

#include "render/shader/float3.h"

namespace glint::render::shader {

// A rotation matrix by rows: the image of a direction d is (dot(x, d), dot(y, d), dot(z, d)).
struct RotationMatrix {
    float3 x, y, z;
};
// Cycles' euler_to_transform: the rotation by euler.x about X, then euler.y about Y, then
// euler.z about Z (radians), i.e. Rz * Ry * Rx.
RotationMatrix euler_xyz_to_matrix(float3 euler);
// m * d, and its inverse transpose(m) * d.
float3 rotate_direction(const RotationMatrix& m, float3 d);
float3 rotate_direction_transposed(const RotationMatrix& m, float3 d);
// Rodrigues' rotation of p by angle (radians, right-handed) about a unit axis, with Cycles'
// term order.
float3 rotate_around_axis(float3 p, float3 unit_axis, float angle);

// ShaderNodeMapping.vector_type.
enum class MappingType { POINT, TEXTURE, VECTOR, NORMAL };
bool parse_mapping_type(std::string_view id, MappingType* out);
// Mapping node, with R = euler_xyz_to_matrix(rotation):
//   POINT    R (vector * scale) + location
//   TEXTURE  transpose(R) (vector - location) / scale   (a zero scale component gives 0)
//   VECTOR   R (vector * scale)                          (location unused)
//   NORMAL   normalize(R (vector / scale))               (zero-safe divide and normalize)
float3 mapping_node(MappingType type, float3 vector, float3 location, float3 rotation,
                    float3 scale);

// ShaderNodeVectorRotate.rotation_type.
enum class VectorRotateType { AXIS_ANGLE, X_AXIS, Y_AXIS, Z_AXIS, EULER_XYZ };
bool parse_vector_rotate_type(std::string_view id, VectorRotateType* out);
// Vector Rotate node: rotates vector about center. AXIS_ANGLE uses axis (normalized; a zero
// axis returns vector unchanged) and angle; X/Y/Z_AXIS use angle about that axis; EULER_XYZ
// uses rotation as Euler XYZ angles. invert rotates the other way (negated angle, or the
// transposed Euler matrix).
float3 vector_rotate_node(VectorRotateType type, float3 vector, float3 center, float3 axis,
                          float angle, float3 rotation, bool invert);

}  // namespace glint::render::shader
