#include "core/transform.h"

#include <cmath>
#include <utility>

#include "core/error.h"
#include "core/float.h"

namespace glint {

Matrix4 Matrix4::operator*(const Matrix4& o) const {
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += m[i][k] * o.m[k][j];
            r.m[i][j] = s;
        }
    return r;
}

Matrix4 Matrix4::transposed() const {
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = m[j][i];
    return r;
}

bool Matrix4::inverse(Matrix4* out) const {
    // Gauss-Jordan elimination with partial pivoting.
    double a[4][8];
    double scale = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            a[i][j] = m[i][j];
            a[i][j + 4] = (i == j) ? 1.0 : 0.0;
            scale = std::max(scale, std::fabs(m[i][j]));
        }
    if (!(scale > 0) || !std::isfinite(scale)) return false;
    for (int c = 0; c < 4; ++c) {
        int piv = c;
        for (int r = c + 1; r < 4; ++r)
            if (std::fabs(a[r][c]) > std::fabs(a[piv][c])) piv = r;
        if (std::fabs(a[piv][c]) <= scale * 1e-300) return false;
        if (piv != c)
            for (int j = 0; j < 8; ++j) std::swap(a[c][j], a[piv][j]);
        double inv = 1.0 / a[c][c];
        for (int j = 0; j < 8; ++j) a[c][j] *= inv;
        for (int r = 0; r < 4; ++r) {
            if (r == c) continue;
            double f = a[r][c];
            if (f == 0) continue;
            for (int j = 0; j < 8; ++j) a[r][j] -= f * a[c][j];
        }
    }
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            if (!std::isfinite(a[i][j + 4])) return false;
            out->m[i][j] = a[i][j + 4];
        }
    return true;
}

Transform Transform::from_matrix(const Matrix4& m) {
    Matrix4 inv;
    if (!m.inverse(&inv)) throw Error(ErrorKind::Scene, {}, "singular transformation matrix");
    return {m, inv};
}

Transform Transform::translate(const Vec3& d) {
    Matrix4 m, inv;
    for (int i = 0; i < 3; ++i) {
        m.m[i][3] = d[i];
        inv.m[i][3] = -d[i];
    }
    return {m, inv};
}

Transform Transform::scale(const Vec3& s) {
    if (s.x == 0 || s.y == 0 || s.z == 0)
        throw Error(ErrorKind::Scene, {}, "scale by zero makes the transformation singular");
    Matrix4 m, inv;
    for (int i = 0; i < 3; ++i) {
        m.m[i][i] = s[i];
        inv.m[i][i] = 1.0 / s[i];
    }
    return {m, inv};
}

namespace {

// Exact values for multiples of 90 degrees keep axis-aligned rotations exact.
void sin_cos_degrees(double deg, double* s, double* c) {
    double r = std::fmod(deg, 360.0);
    if (r < 0) r += 360.0;
    if (r == 0) { *s = 0; *c = 1; return; }
    if (r == 90) { *s = 1; *c = 0; return; }
    if (r == 180) { *s = 0; *c = -1; return; }
    if (r == 270) { *s = -1; *c = 0; return; }
    double rad = deg * kPi / 180.0;
    *s = std::sin(rad);
    *c = std::cos(rad);
}

Transform rotation(int axis, double degrees) {
    double s, c;
    sin_cos_degrees(degrees, &s, &c);
    int a = (axis + 1) % 3, b = (axis + 2) % 3;
    Matrix4 m;
    m.m[a][a] = c;
    m.m[a][b] = -s;
    m.m[b][a] = s;
    m.m[b][b] = c;
    return {m, m.transposed()};
}

}  // namespace

Transform Transform::rotate_xyz_degrees(const Vec3& deg) {
    // POV-Ray rotates about x first, then y, then z. Numerically its matrices are the usual
    // right-handed rotation matrices; the left-handed coordinate system only changes how the
    // result looks on screen.
    Transform t;
    if (deg.x != 0) t = t.then(rotation(0, deg.x));
    if (deg.y != 0) t = t.then(rotation(1, deg.y));
    if (deg.z != 0) t = t.then(rotation(2, deg.z));
    return t;
}

Transform Transform::rotate_axis(const Vec3& axis, double degrees) {
    Vec3 a = normalize(axis);
    double s, c;
    sin_cos_degrees(degrees, &s, &c);
    Matrix4 m;
    m.m[0][0] = a.x * a.x + (1 - a.x * a.x) * c;
    m.m[0][1] = a.x * a.y * (1 - c) - a.z * s;
    m.m[0][2] = a.x * a.z * (1 - c) + a.y * s;
    m.m[1][0] = a.x * a.y * (1 - c) + a.z * s;
    m.m[1][1] = a.y * a.y + (1 - a.y * a.y) * c;
    m.m[1][2] = a.y * a.z * (1 - c) - a.x * s;
    m.m[2][0] = a.x * a.z * (1 - c) - a.y * s;
    m.m[2][1] = a.y * a.z * (1 - c) + a.x * s;
    m.m[2][2] = a.z * a.z + (1 - a.z * a.z) * c;
    return {m, m.transposed()};
}

Transform Transform::pov_matrix(const double v[12]) {
    // POV-Ray multiplies row vectors: p' = p * M with M's rows (v0 v1 v2 0), (v3 v4 v5 0),
    // (v6 v7 v8 0), (v9 v10 v11 1). In column-vector form that is the transpose.
    Matrix4 m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 3; ++c) m.m[c][r] = v[r * 3 + c];
    return from_matrix(m);
}

Transform Transform::then(const Transform& next) const {
    return {next.m_ * m_, inv_ * next.inv_};
}

Vec3 Transform::point(const Vec3& p) const {
    const auto& a = m_.m;
    return {a[0][0] * p.x + a[0][1] * p.y + a[0][2] * p.z + a[0][3],
            a[1][0] * p.x + a[1][1] * p.y + a[1][2] * p.z + a[1][3],
            a[2][0] * p.x + a[2][1] * p.y + a[2][2] * p.z + a[2][3]};
}

Vec3 Transform::vector(const Vec3& v) const {
    const auto& a = m_.m;
    return {a[0][0] * v.x + a[0][1] * v.y + a[0][2] * v.z,
            a[1][0] * v.x + a[1][1] * v.y + a[1][2] * v.z,
            a[2][0] * v.x + a[2][1] * v.y + a[2][2] * v.z};
}

Vec3 Transform::normal(const Vec3& n) const {
    const auto& a = inv_.m;
    return {a[0][0] * n.x + a[1][0] * n.y + a[2][0] * n.z,
            a[0][1] * n.x + a[1][1] * n.y + a[2][1] * n.z,
            a[0][2] * n.x + a[1][2] * n.y + a[2][2] * n.z};
}

Vec3 Transform::inverse_point(const Vec3& p) const { return inverse().point(p); }
Vec3 Transform::inverse_vector(const Vec3& v) const { return inverse().vector(v); }

Bounds3 Transform::bounds(const Bounds3& b) const {
    if (b.empty()) return b;
    Bounds3 r;
    if (b.is_infinite()) {
        // A box open along some axes (a half-space, an infinite cylinder's slab) keeps its
        // finite sides under a transform that maps each axis onto one axis (scales, mirrors,
        // axis swaps, translations); any other turns it unbounded.
        const auto& a = m_.m;
        Bounds3 out;
        for (int i = 0; i < 3; ++i) {
            int src = -1;
            for (int j = 0; j < 3; ++j) {
                if (a[i][j] == 0) continue;
                if (src >= 0) return Bounds3{Vec3(-kInfinity), Vec3(kInfinity)};
                src = j;
            }
            if (src < 0) return Bounds3{Vec3(-kInfinity), Vec3(kInfinity)};
            for (int k = 0; k < 3; ++k)
                if (k != i && a[k][src] != 0) return Bounds3{Vec3(-kInfinity), Vec3(kInfinity)};
            const double s = a[i][src], t = a[i][3];
            double lo = s * b.lo[src] + t, hi = s * b.hi[src] + t;
            if (lo > hi) std::swap(lo, hi);
            // Widen the finite sides by their rounding.
            if (std::isfinite(lo)) lo -= gamma(3) * (std::fabs(lo) + std::fabs(t));
            if (std::isfinite(hi)) hi += gamma(3) * (std::fabs(hi) + std::fabs(t));
            out.lo[i] = lo;
            out.hi[i] = hi;
        }
        return out;
    }
    for (int i = 0; i < 8; ++i) {
        Vec3 c{(i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z};
        r.extend(point(c));
    }
    // Widen by the rounding error of the corner transform so a transformed box still encloses.
    Vec3 e = max(point_error(b.lo), point_error(b.hi));
    r.lo -= e;
    r.hi += e;
    return r;
}

Vec3 Transform::point_error(const Vec3& p) const {
    const auto& a = m_.m;
    Vec3 e;
    for (int i = 0; i < 3; ++i)
        e[i] = gamma(3) * (std::fabs(a[i][0] * p.x) + std::fabs(a[i][1] * p.y) +
                           std::fabs(a[i][2] * p.z) + std::fabs(a[i][3]));
    return e;
}

}  // namespace glint
