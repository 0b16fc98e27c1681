// The shader VM's value type: three single-precision floats, as Cycles' SVM computes. Node
// functions work in float so that hashes of coordinates and noise give Cycles' values bit for
// bit where Cycles' own code would (Cycles 3.4, kernel/svm).
#pragma once

#include <cmath>

#include "core/math.h"

namespace glint::render::shader {

struct float3 {
    float x = 0, y = 0, z = 0;
    constexpr float3() = default;
    constexpr float3(float a, float b, float c) : x(a), y(b), z(c) {}
    constexpr explicit float3(float a) : x(a), y(a), z(a) {}
    explicit float3(const Vec3& v)
        : x(static_cast<float>(v.x)), y(static_cast<float>(v.y)), z(static_cast<float>(v.z)) {}
    Vec3 to_vec3() const { return Vec3(x, y, z); }
    float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

struct float4 {
    float x = 0, y = 0, z = 0, w = 0;
};

inline float3 operator+(float3 a, float3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline float3 operator-(float3 a, float3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline float3 operator-(float3 a) { return {-a.x, -a.y, -a.z}; }
inline float3 operator*(float3 a, float3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline float3 operator*(float3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
inline float3 operator*(float s, float3 a) { return {a.x * s, a.y * s, a.z * s}; }
inline float3 operator/(float3 a, float3 b) { return {a.x / b.x, a.y / b.y, a.z / b.z}; }
inline float3 operator/(float3 a, float s) { return {a.x / s, a.y / s, a.z / s}; }
inline float3& operator+=(float3& a, float3 b) { return a = a + b; }
inline float3& operator-=(float3& a, float3 b) { return a = a - b; }
inline float3& operator*=(float3& a, float3 b) { return a = a * b; }
inline float3& operator*=(float3& a, float s) { return a = a * s; }
inline bool operator==(float3 a, float3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

inline float dot(float3 a, float3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline float3 cross(float3 a, float3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline float len(float3 a) { return std::sqrt(dot(a, a)); }
// Cycles' safe_normalize: zero stays zero.
inline float3 safe_normalize(float3 a) {
    const float t = len(a);
    return t != 0.0f ? a * (1.0f / t) : a;
}

}  // namespace glint::render::shader
