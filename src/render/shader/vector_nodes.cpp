// Cycles 3.4's Mapping and Vector Rotate node arithmetic (kernel/svm/mapping_util.h,
// vector_rotate.h; util/transform.h, util/math.h), restated in single precision.
#include "render/shader/vector_nodes.h"

#include "render/shader/enum_table.h"

#include <array>
#include <cmath>
#include <utility>

namespace glint::render::shader {
namespace {

float safe_divide(float a, float b) { return b != 0.0f ? a / b : 0.0f; }
float3 safe_divide(float3 a, float3 b) {
    return {safe_divide(a.x, b.x), safe_divide(a.y, b.y), safe_divide(a.z, b.z)};
}


}  // namespace

RotationMatrix euler_xyz_to_matrix(float3 euler) {
    const float cx = std::cos(euler.x), cy = std::cos(euler.y), cz = std::cos(euler.z);
    const float sx = std::sin(euler.x), sy = std::sin(euler.y), sz = std::sin(euler.z);
    RotationMatrix m;
    m.x = {cy * cz, sy * sx * cz - cx * sz, sy * cx * cz + sx * sz};
    m.y = {cy * sz, sy * sx * sz + cx * cz, sy * cx * sz - sx * cz};
    m.z = {-sy, cy * sx, cy * cx};
    return m;
}

float3 rotate_direction(const RotationMatrix& m, float3 d) {
    // Cycles' SSE order: the z column first, then y, then x.
    return {d.x * m.x.x + (d.y * m.x.y + d.z * m.x.z), d.x * m.y.x + (d.y * m.y.y + d.z * m.y.z),
            d.x * m.z.x + (d.y * m.z.y + d.z * m.z.z)};
}

float3 rotate_direction_transposed(const RotationMatrix& m, float3 d) {
    const float3 cx(m.x.x, m.y.x, m.z.x), cy(m.x.y, m.y.y, m.z.y), cz(m.x.z, m.y.z, m.z.z);
    return {dot(cx, d), dot(cy, d), dot(cz, d)};
}

float3 rotate_around_axis(float3 p, float3 unit_axis, float angle) {
    const float c = std::cos(angle), s = std::sin(angle), k = 1.0f - c;
    const float ax = unit_axis.x, ay = unit_axis.y, az = unit_axis.z;
    return {(c + k * ax * ax) * p.x + (k * ax * ay - az * s) * p.y + (k * ax * az + ay * s) * p.z,
            (k * ax * ay + az * s) * p.x + (c + k * ay * ay) * p.y + (k * ay * az - ax * s) * p.z,
            (k * ax * az - ay * s) * p.x + (k * ay * az + ax * s) * p.y + (c + k * az * az) * p.z};
}

bool parse_mapping_type(std::string_view id, MappingType* out) {
    static constexpr std::array<std::pair<std::string_view, MappingType>, 4> kTable{{
        {"POINT", MappingType::POINT},
        {"TEXTURE", MappingType::TEXTURE},
        {"VECTOR", MappingType::VECTOR},
        {"NORMAL", MappingType::NORMAL},
    }};
    return parse_enum(id, kTable, out);
}

float3 mapping_node(MappingType type, float3 vector, float3 location, float3 rotation,
                    float3 scale) {
    const RotationMatrix r = euler_xyz_to_matrix(rotation);
    switch (type) {
        case MappingType::POINT:
            return rotate_direction(r, vector * scale) + location;
        case MappingType::TEXTURE:
            return safe_divide(rotate_direction_transposed(r, vector - location), scale);
        case MappingType::VECTOR:
            return rotate_direction(r, vector * scale);
        case MappingType::NORMAL:
            return safe_normalize(rotate_direction(r, safe_divide(vector, scale)));
    }
    return float3(0.0f);
}

bool parse_vector_rotate_type(std::string_view id, VectorRotateType* out) {
    using T = VectorRotateType;
    static constexpr std::array<std::pair<std::string_view, T>, 5> kTable{{
        {"AXIS_ANGLE", T::AXIS_ANGLE},
        {"X_AXIS", T::X_AXIS},
        {"Y_AXIS", T::Y_AXIS},
        {"Z_AXIS", T::Z_AXIS},
        {"EULER_XYZ", T::EULER_XYZ},
    }};
    return parse_enum(id, kTable, out);
}

float3 vector_rotate_node(VectorRotateType type, float3 vector, float3 center, float3 axis,
                          float angle, float3 rotation, bool invert) {
    if (type == VectorRotateType::EULER_XYZ) {
        const RotationMatrix r = euler_xyz_to_matrix(rotation);
        const float3 d = vector - center;
        return (invert ? rotate_direction_transposed(r, d) : rotate_direction(r, d)) + center;
    }
    float3 unit;
    switch (type) {
        case VectorRotateType::X_AXIS:
            unit = {1.0f, 0.0f, 0.0f};
            break;
        case VectorRotateType::Y_AXIS:
            unit = {0.0f, 1.0f, 0.0f};
            break;
        case VectorRotateType::Z_AXIS:
            unit = {0.0f, 0.0f, 1.0f};
            break;
        default: {
            const float length = len(axis);
            if (length == 0.0f) return vector;  // no axis: no rotation
            unit = axis / length;
            break;
        }
    }
    return rotate_around_axis(vector - center, unit, invert ? -angle : angle) + center;
}

}  // namespace glint::render::shader
