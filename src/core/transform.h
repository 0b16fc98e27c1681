// Affine transforms as a 4x4 matrix with its inverse kept alongside, so that rays can be taken
// into object space and normals back out without inverting per use. Composition follows
// POV-Ray: `a.then(b)` applies a first, then b (POV-Ray lists transforms in the order applied).
#pragma once

#include "core/math.h"

namespace glint {

struct Matrix4 {
    double m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};

    static Matrix4 identity() { return {}; }
    // Row-major, column-vector convention: p' = M * p.
    Matrix4 operator*(const Matrix4& o) const;
    bool operator==(const Matrix4&) const = default;
    Matrix4 transposed() const;
    // Returns false if the matrix is singular (or nearly so relative to its scale).
    bool inverse(Matrix4* out) const;
    bool is_identity() const { return *this == Matrix4{}; }
};

class Transform {
public:
    Transform() = default;
    // `inv` must be the inverse of `m`.
    Transform(const Matrix4& m, const Matrix4& inv) : m_(m), inv_(inv) {}
    // Throws glint::Error if `m` is singular.
    static Transform from_matrix(const Matrix4& m);

    static Transform translate(const Vec3& d);
    static Transform scale(const Vec3& s);  // throws if a component is zero
    // POV-Ray's `rotate <a,b,c>`: degrees about x, then y, then z.
    static Transform rotate_xyz_degrees(const Vec3& degrees);
    static Transform rotate_axis(const Vec3& axis, double degrees);
    // POV-Ray's `matrix <m00,m01,m02, m10,m11,m12, m20,m21,m22, m30,m31,m32>`
    // (row-vector convention: the last row is the translation).
    static Transform pov_matrix(const double values[12]);

    // The transform that applies *this first, then `next`.
    Transform then(const Transform& next) const;
    Transform inverse() const { return {inv_, m_}; }

    const Matrix4& matrix() const { return m_; }
    const Matrix4& inverse_matrix() const { return inv_; }
    bool is_identity() const { return m_.is_identity(); }
    bool operator==(const Transform& o) const { return m_ == o.m_; }

    Vec3 point(const Vec3& p) const;
    Vec3 vector(const Vec3& v) const;
    // Normals transform with the inverse transpose; the result is not normalized.
    Vec3 normal(const Vec3& n) const;
    Vec3 inverse_point(const Vec3& p) const;
    Vec3 inverse_vector(const Vec3& v) const;
    Bounds3 bounds(const Bounds3& b) const;

    // Conservative absolute error bound of point(p) in floating point (pbrt-v4 style, gamma(3)).
    Vec3 point_error(const Vec3& p) const;

private:
    Matrix4 m_;
    Matrix4 inv_;
};

}  // namespace glint
