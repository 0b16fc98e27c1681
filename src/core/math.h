// Small value types for geometry and color used by every layer of glint: the IR, the
// importers and the renderer. Geometry is double precision throughout (POV-Ray scenes span
// many orders of magnitude); colors are double too so the film is the only place that rounds.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace glint {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
// POV-Ray's EPSILON (source/backend/configbackend.h): the tolerance of POV-Ray's own tests
// (near-black colors, degenerate vectors, pattern cell edges) wherever glint reproduces one.
constexpr double kPovEpsilon = 1.0e-10;

struct Vec2 {
    double x = 0, y = 0;
    constexpr Vec2() = default;
    constexpr Vec2(double x_, double y_) : x(x_), y(y_) {}
    constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
    constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
    constexpr Vec2 operator*(double s) const { return {x * s, y * s}; }
    constexpr bool operator==(const Vec2&) const = default;
};

struct Vec3 {
    double x = 0, y = 0, z = 0;
    constexpr Vec3() = default;
    constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
    constexpr explicit Vec3(double s) : x(s), y(s), z(s) {}

    constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr Vec3 operator*(const Vec3& o) const { return {x * o.x, y * o.y, z * o.z}; }
    constexpr Vec3 operator/(const Vec3& o) const { return {x / o.x, y / o.y, z / o.z}; }
    constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
    constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
    constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
    constexpr Vec3& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }
    constexpr bool operator==(const Vec3&) const = default;
};

constexpr Vec3 operator*(double s, const Vec3& v) { return v * s; }
constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const Vec3& v) { return std::sqrt(dot(v, v)); }
constexpr double length_squared(const Vec3& v) { return dot(v, v); }
inline Vec3 normalize(const Vec3& v) { return v / length(v); }
inline Vec3 abs(const Vec3& v) { return {std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}; }
inline Vec3 min(const Vec3& a, const Vec3& b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
inline Vec3 max(const Vec3& a, const Vec3& b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
inline double max_component(const Vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }
inline bool is_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Linear RGB. POV-Ray's filter and transmit channels live in ColorFT (src/scene/color.h).
struct Color {
    double r = 0, g = 0, b = 0;
    constexpr Color() = default;
    constexpr Color(double r_, double g_, double b_) : r(r_), g(g_), b(b_) {}
    constexpr explicit Color(double s) : r(s), g(s), b(s) {}

    constexpr Color operator+(const Color& o) const { return {r + o.r, g + o.g, b + o.b}; }
    constexpr Color operator-(const Color& o) const { return {r - o.r, g - o.g, b - o.b}; }
    constexpr Color operator*(const Color& o) const { return {r * o.r, g * o.g, b * o.b}; }
    constexpr Color operator*(double s) const { return {r * s, g * s, b * s}; }
    constexpr Color operator/(double s) const { return {r / s, g / s, b / s}; }
    constexpr Color& operator+=(const Color& o) { r += o.r; g += o.g; b += o.b; return *this; }
    constexpr Color& operator*=(const Color& o) { r *= o.r; g *= o.g; b *= o.b; return *this; }
    constexpr Color& operator*=(double s) { r *= s; g *= s; b *= s; return *this; }
    constexpr bool operator==(const Color&) const = default;
    constexpr double max() const { return std::max(r, std::max(g, b)); }
    constexpr double sum() const { return r + g + b; }
    bool is_black() const { return r == 0 && g == 0 && b == 0; }
};
constexpr Color operator*(double s, const Color& c) { return c * s; }

// Axis-aligned bounding box; an empty box has lo > hi.
struct Bounds3 {
    Vec3 lo{kInfinity, kInfinity, kInfinity};
    Vec3 hi{-kInfinity, -kInfinity, -kInfinity};

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void extend(const Vec3& p) { lo = min(lo, p); hi = max(hi, p); }
    void extend(const Bounds3& b) { lo = min(lo, b.lo); hi = max(hi, b.hi); }
    Vec3 centroid() const { return (lo + hi) * 0.5; }
    Vec3 diagonal() const { return hi - lo; }
    bool is_infinite() const { return !is_finite(lo) || !is_finite(hi); }
    double surface_area() const {
        Vec3 d = diagonal();
        return empty() ? 0.0 : 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
};

}  // namespace glint
