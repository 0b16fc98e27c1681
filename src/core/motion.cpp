#include "core/motion.h"

#include <algorithm>
#include <cmath>

namespace glint {
namespace {

using M3 = double[3][3];

double det3(const M3& a) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

// The inverse transposed, through the cofactors; false when singular.
bool inverse_transposed(const M3& a, M3& out) {
    const double det = det3(a);
    if (!(std::fabs(det) > 0) || !std::isfinite(det)) return false;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            out[i][j] = (a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]) / det;
        }
    return true;
}

void quat_to_matrix(const double q[4], M3& r) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    r[0][0] = 1 - 2 * (y * y + z * z);
    r[0][1] = 2 * (x * y - w * z);
    r[0][2] = 2 * (x * z + w * y);
    r[1][0] = 2 * (x * y + w * z);
    r[1][1] = 1 - 2 * (x * x + z * z);
    r[1][2] = 2 * (y * z - w * x);
    r[2][0] = 2 * (x * z - w * y);
    r[2][1] = 2 * (y * z + w * x);
    r[2][2] = 1 - 2 * (x * x + y * y);
}

// Shepperd's method: the largest of w, x, y, z is found first, so nothing divides by a small
// number.
void matrix_to_quat(const M3& r, double q[4]) {
    const double trace = r[0][0] + r[1][1] + r[2][2];
    if (trace > 0) {
        const double s = 2 * std::sqrt(trace + 1);
        q[0] = s / 4, q[1] = (r[2][1] - r[1][2]) / s, q[2] = (r[0][2] - r[2][0]) / s,
        q[3] = (r[1][0] - r[0][1]) / s;
    } else if (r[0][0] >= r[1][1] && r[0][0] >= r[2][2]) {
        const double s = 2 * std::sqrt(std::max(0.0, 1 + r[0][0] - r[1][1] - r[2][2]));
        q[0] = (r[2][1] - r[1][2]) / s, q[1] = s / 4, q[2] = (r[0][1] + r[1][0]) / s,
        q[3] = (r[0][2] + r[2][0]) / s;
    } else if (r[1][1] >= r[2][2]) {
        const double s = 2 * std::sqrt(std::max(0.0, 1 + r[1][1] - r[0][0] - r[2][2]));
        q[0] = (r[0][2] - r[2][0]) / s, q[1] = (r[0][1] + r[1][0]) / s, q[2] = s / 4,
        q[3] = (r[1][2] + r[2][1]) / s;
    } else {
        const double s = 2 * std::sqrt(std::max(0.0, 1 + r[2][2] - r[0][0] - r[1][1]));
        q[0] = (r[1][0] - r[0][1]) / s, q[1] = (r[0][2] + r[2][0]) / s,
        q[2] = (r[1][2] + r[2][1]) / s, q[3] = s / 4;
    }
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (int i = 0; i < 4; ++i) q[i] /= n;
}

double qdot(const double a[4], const double b[4]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

// Cycles' quat_interpolate: slerp, or a normalized lerp where the two are within ~3.6
// degrees (there slerp's division loses precision).
void quat_interpolate(const double a[4], const double b[4], double t, double out[4]) {
    const double c = qdot(a, b);
    double n = 0;
    if (c > 0.9995) {
        for (int i = 0; i < 4; ++i) out[i] = (1 - t) * a[i] + t * b[i];
        n = std::sqrt(qdot(out, out));
        for (int i = 0; i < 4; ++i) out[i] /= n;
        return;
    }
    const double theta = std::acos(std::clamp(c, -1.0, 1.0));
    double perp[4];
    for (int i = 0; i < 4; ++i) perp[i] = b[i] - a[i] * c;
    n = std::sqrt(qdot(perp, perp));
    const double ct = std::cos(theta * t), st = std::sin(theta * t);
    for (int i = 0; i < 4; ++i) out[i] = a[i] * ct + perp[i] / n * st;
}

bool zero_scale(const DecomposedTransform& d) {
    return d.scale[0][0] == 0 && d.scale[1][1] == 0 && d.scale[2][2] == 0;
}

Vec3 apply3(const double a[3][3], const Vec3& v) {
    return {a[0][0] * v.x + a[0][1] * v.y + a[0][2] * v.z,
            a[1][0] * v.x + a[1][1] * v.y + a[1][2] * v.z,
            a[2][0] * v.x + a[2][1] * v.y + a[2][2] * v.z};
}

Vec3 corner(const Bounds3& b, int i) {
    return {(i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z};
}

}  // namespace

DecomposedTransform decompose(const Matrix4& m) {
    DecomposedTransform d;
    d.translation = {m.m[0][3], m.m[1][3], m.m[2][3]};
    M3 lin, r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) lin[i][j] = r[i][j] = m.m[i][j];
    bool ok = true;
    for (int it = 0; it < 100 && ok; ++it) {
        M3 rit;
        if (!inverse_transposed(r, rit)) {
            ok = false;
            break;
        }
        double change = 0;
        for (int i = 0; i < 3; ++i) {
            double row = 0;
            for (int j = 0; j < 3; ++j) {
                const double next = 0.5 * (r[i][j] + rit[i][j]);
                row += std::fabs(next - r[i][j]);
                r[i][j] = next;
            }
            change = std::max(change, row);
        }
        if (change <= 1e-14) break;
    }
    if (!ok) {  // singular: no rotation to speak of; the scale keeps it all
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) r[i][j] = i == j ? 1 : 0;
    }
    if (det3(r) < 0)
        for (auto& row : r)
            for (double& v : row) v = -v;
    matrix_to_quat(r, d.q);
    // scale = R^T * M (R orthonormal).
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double s = 0;
            for (int k = 0; k < 3; ++k) s += r[k][i] * lin[k][j];
            d.scale[i][j] = s;
        }
    return d;
}

Matrix4 compose(const DecomposedTransform& d) {
    M3 r;
    quat_to_matrix(d.q, r);
    Matrix4 m;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double s = 0;
            for (int k = 0; k < 3; ++k) s += r[i][k] * d.scale[k][j];
            m.m[i][j] = s;
        }
    }
    m.m[0][3] = d.translation.x;
    m.m[1][3] = d.translation.y;
    m.m[2][3] = d.translation.z;
    return m;
}

MotionTransform::MotionTransform(const std::vector<Matrix4>& steps) {
    for (const Matrix4& m : steps) {
        steps_.push_back(decompose(m));
        const size_t n = steps_.size();
        if (n > 1 && qdot(steps_[n - 2].q, steps_[n - 1].q) < 0)
            for (double& v : steps_[n - 1].q) v = -v;
    }
    for (size_t i = 0; i < steps_.size(); ++i) {
        if (!zero_scale(steps_[i])) continue;
        const DecomposedTransform* from = i > 0                     ? &steps_[i - 1]
                                          : i + 1 < steps_.size() ? &steps_[i + 1]
                                                                  : nullptr;
        if (from) std::copy(from->q, from->q + 4, steps_[i].q);
    }
    if (steps_.size() == 1) steps_.push_back(steps_[0]);
}

Matrix4 MotionTransform::matrix_at(double time) const {
    if (steps_.empty()) return Matrix4{};
    const int last = static_cast<int>(steps_.size()) - 1;
    const double x = std::clamp(time, 0.0, 1.0) * last;
    const int step = std::min(static_cast<int>(x), last - 1);
    const double t = x - step;
    const DecomposedTransform& a = steps_[static_cast<size_t>(step)];
    const DecomposedTransform& b = steps_[static_cast<size_t>(step) + 1];
    DecomposedTransform d;
    quat_interpolate(a.q, b.q, t, d.q);
    d.translation = a.translation * (1 - t) + b.translation * t;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) d.scale[i][j] = (1 - t) * a.scale[i][j] + t * b.scale[i][j];
    return compose(d);
}

bool MotionTransform::at(double time, Transform* out) const {
    const Matrix4 m = matrix_at(time);
    Matrix4 inv;
    if (!m.inverse(&inv)) return false;
    *out = Transform(m, inv);
    return true;
}

Bounds3 MotionTransform::bounds(const Bounds3& local) const {
    if (local.empty() || steps_.empty()) return local;
    if (local.is_infinite()) return {Vec3(-kInfinity), Vec3(kInfinity)};
    // Samples per step: the padding shrinks with their number, the cost (once per object at
    // prepare) grows with it.
    constexpr int kSamples = 32;
    Bounds3 out;
    const int last = static_cast<int>(steps_.size()) - 1;
    for (int s = 0; s < last; ++s) {
        const DecomposedTransform& a = steps_[static_cast<size_t>(s)];
        const DecomposedTransform& b = steps_[static_cast<size_t>(s) + 1];
        // A point c of the box moves at most at |dT| + |dR/dt| |S(t) c| + |dS c| per unit of
        // the step's time: slerp turns at a constant 2 theta (theta the quaternions' angle),
        // |S(t) c| is convex in t and c, so the corners at the two steps bound it.
        const double theta = std::acos(std::clamp(std::fabs(qdot(a.q, b.q)), -1.0, 1.0));
        double reach = 0, stretch = 0;
        double ds[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) ds[i][j] = b.scale[i][j] - a.scale[i][j];
        for (int c = 0; c < 8; ++c) {
            const Vec3 p = corner(local, c);
            reach = std::max({reach, length(apply3(a.scale, p)), length(apply3(b.scale, p))});
            stretch = std::max(stretch, length(apply3(ds, p)));
        }
        const double speed = length(b.translation - a.translation) + 2 * theta * reach + stretch;
        // Every time lies within half a sample interval of a sample. The normalized lerp
        // (quaternions within 0.0316 rad) turns at a rate within 0.1% of constant; 2% more
        // covers it and the rounding.
        const double pad = 0.51 * speed / kSamples;
        for (int k = 0; k <= kSamples; ++k) {
            const double time = (s + static_cast<double>(k) / kSamples) / last;
            const Matrix4 m = matrix_at(time);
            Bounds3 box;
            for (int c = 0; c < 8; ++c) {
                const Vec3 p = corner(local, c);
                box.extend(Vec3(m.m[0][0] * p.x + m.m[0][1] * p.y + m.m[0][2] * p.z + m.m[0][3],
                                m.m[1][0] * p.x + m.m[1][1] * p.y + m.m[1][2] * p.z + m.m[1][3],
                                m.m[2][0] * p.x + m.m[2][1] * p.y + m.m[2][2] * p.z + m.m[2][3]));
            }
            box.lo = box.lo - Vec3(pad);
            box.hi = box.hi + Vec3(pad);
            out.extend(box);
        }
    }
    return out;
}

}  // namespace glint
