// src/core/transform.cpp: POV-Ray transform semantics, inverses, normals, bounds, error bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.h"
#include "core/float.h"
#include "core/transform.h"

namespace glint {
namespace {

void expect_vec(const Vec3& a, const Vec3& b, double tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Transform, TranslateScaleOrder) {
    // POV-Ray lists transforms in the order applied: scale 2, then translate x 1.
    Transform t = Transform::scale({2, 2, 2}).then(Transform::translate({1, 0, 0}));
    EXPECT_EQ(t.point({1, 1, 1}), Vec3(3, 2, 2));
    EXPECT_EQ(t.vector({1, 1, 1}), Vec3(2, 2, 2));
    Transform u = Transform::translate({1, 0, 0}).then(Transform::scale({2, 2, 2}));
    EXPECT_EQ(u.point({1, 1, 1}), Vec3(4, 2, 2));
    EXPECT_EQ(t.inverse_point(t.point({0.5, -3, 7})), Vec3(0.5, -3, 7));
}

TEST(Transform, RotateMatchesPovRay) {
    // POV-Ray: rotate <0, 90, 0> takes +x to -z and +z to +x; rotate z 90 takes +x to +y.
    Transform y = Transform::rotate_xyz_degrees({0, 90, 0});
    EXPECT_EQ(y.point({1, 0, 0}), Vec3(0, 0, -1));
    EXPECT_EQ(y.point({0, 0, 1}), Vec3(1, 0, 0));
    Transform z = Transform::rotate_xyz_degrees({0, 0, 90});
    EXPECT_EQ(z.point({1, 0, 0}), Vec3(0, 1, 0));
    Transform x = Transform::rotate_xyz_degrees({90, 0, 0});
    EXPECT_EQ(x.point({0, 1, 0}), Vec3(0, 0, 1));
    // x first, then y, then z.
    Transform xyz = Transform::rotate_xyz_degrees({90, 90, 0});
    Transform seq = x.then(y);
    EXPECT_EQ(xyz.point({0.3, 0.5, 0.7}), seq.point({0.3, 0.5, 0.7}));
}

TEST(Transform, RotateAxisAgreesWithEulerOnAxes) {
    Transform a = Transform::rotate_axis({0, 1, 0}, 33);
    Transform e = Transform::rotate_xyz_degrees({0, 33, 0});
    expect_vec(a.point({1, 2, 3}), e.point({1, 2, 3}), 1e-15);
    // A rotation keeps lengths and its inverse is its transpose.
    Transform r = Transform::rotate_axis({1, 2, 3}, 71);
    Vec3 p(0.3, -1, 2);
    EXPECT_NEAR(length(r.point(p)), length(p), 1e-14);
    expect_vec(r.inverse_point(r.point(p)), p, 1e-14);
}

TEST(Transform, PovMatrixRowVectorConvention) {
    // matrix <1,0,0, 0,1,0, 0,0,1, 5,6,7> is a translation by <5,6,7>.
    double v[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 5, 6, 7};
    EXPECT_EQ(Transform::pov_matrix(v).point({1, 1, 1}), Vec3(6, 7, 8));
    // A shear: matrix <1,1,0, 0,1,0, 0,0,1, 0,0,0> maps x to x + y... in POV-Ray's row form
    // p' = p * M: y' = x*1 + y*1.
    double s[12] = {1, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
    EXPECT_EQ(Transform::pov_matrix(s).point({2, 3, 0}), Vec3(2, 5, 0));
}

TEST(Transform, SingularThrows) {
    EXPECT_THROW(Transform::scale({1, 0, 1}), Error);
    double v[12] = {1, 0, 0, 2, 0, 0, 0, 0, 1, 0, 0, 0};
    EXPECT_THROW(Transform::pov_matrix(v), Error);
}

TEST(Transform, InverseIsInverse) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-3, 3);
    for (int i = 0; i < 100; ++i) {
        Transform t = Transform::rotate_xyz_degrees({u(rng) * 60, u(rng) * 60, u(rng) * 60})
                          .then(Transform::scale({u(rng) + 3.5, 0.5 + std::fabs(u(rng)), 2}))
                          .then(Transform::translate({u(rng), u(rng), u(rng)}));
        Matrix4 prod = t.matrix() * t.inverse_matrix();
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) EXPECT_NEAR(prod.m[r][c], r == c ? 1 : 0, 1e-13);
        Matrix4 inv;
        ASSERT_TRUE(t.matrix().inverse(&inv));
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) EXPECT_NEAR(inv.m[r][c], t.inverse_matrix().m[r][c], 1e-12);
    }
}

TEST(Transform, NormalsStayPerpendicular) {
    Transform t = Transform::scale({1, 4, 0.5}).then(Transform::rotate_axis({1, 1, 0}, 30));
    Vec3 tangent = normalize(Vec3(1, -1, 0.5)), n = normalize(Vec3(1, 1, 0));
    ASSERT_NEAR(dot(tangent, n), 0, 1e-15);
    EXPECT_NEAR(dot(t.vector(tangent), t.normal(n)), 0, 1e-14);
}

TEST(Transform, BoundsEncloseTransformedCorners) {
    Transform t = Transform::rotate_xyz_degrees({10, 20, 30}).then(Transform::translate({1e5, 0, 0}));
    Bounds3 b{Vec3(-1, -2, -3), Vec3(1, 2, 3)};
    Bounds3 tb = t.bounds(b);
    for (int i = 0; i < 8; ++i) {
        Vec3 c{(i & 1) ? 1.0 : -1.0, (i & 2) ? 2.0 : -2.0, (i & 4) ? 3.0 : -3.0};
        Vec3 p = t.point(c);
        for (int a = 0; a < 3; ++a) {
            EXPECT_LE(tb.lo[a], p[a]);
            EXPECT_GE(tb.hi[a], p[a]);
        }
    }
    Bounds3 inf{Vec3(-kInfinity), Vec3(kInfinity)};
    EXPECT_TRUE(t.bounds(inf).is_infinite());
    EXPECT_TRUE(t.bounds(Bounds3{}).empty());
}

// point_error() bounds the difference between the double result and the exact one (computed
// in long double, whose extra bits stand in for exact arithmetic at this size).
TEST(Transform, PointErrorBoundsTheRealError) {
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u(-1, 1);
    int violations = 0;
    for (int i = 0; i < 20000; ++i) {
        double s = std::pow(10.0, 5 * u(rng));
        Transform t = Transform::rotate_xyz_degrees({u(rng) * 180, u(rng) * 180, u(rng) * 180})
                          .then(Transform::scale({1 + std::fabs(u(rng)), 0.3, 2}))
                          .then(Transform::translate({u(rng) * s, u(rng) * s, u(rng) * s}));
        Vec3 p(u(rng) * s, u(rng) * s, u(rng) * s);
        Vec3 q = t.point(p), e = t.point_error(p);
        const auto& m = t.matrix().m;
        for (int r = 0; r < 3; ++r) {
            long double exact = (long double)m[r][0] * p.x + (long double)m[r][1] * p.y +
                                (long double)m[r][2] * p.z + (long double)m[r][3];
            if (std::fabs((long double)q[r] - exact) > e[r]) ++violations;
        }
    }
    EXPECT_EQ(violations, 0);
}

// float.h's bit-level next_up/next_down agree with std::nextafter, including zeros, denormals,
// the largest finite values and infinities.
TEST(Float, NextUpDownMatchNextafter) {
    const double lim = std::numeric_limits<double>::max();
    const double den = std::numeric_limits<double>::denorm_min();
    for (double v : {0.0, -0.0, 1.0, -1.0, 1e-320, -1e-320, 3.5, -2.25, 1e300, -1e300, lim, -lim,
                     den, -den, kInfinity, -kInfinity}) {
        EXPECT_EQ(next_up(v), std::nextafter(v, kInfinity)) << v;
        EXPECT_EQ(next_down(v), std::nextafter(v, -kInfinity)) << v;
    }
    EXPECT_TRUE(std::isnan(next_up(std::nan(""))));
}

// float_up / float_down give the nearest float at or above / at or below a double: the
// reference rounds to nearest and steps with std::nextafter, across zeros, float denormals,
// values that round either way, the edge of the float range and beyond it.
TEST(Float, FloatUpDownBracketTheDouble) {
    const float fmax = std::numeric_limits<float>::max(), finf = std::numeric_limits<float>::infinity();
    std::vector<double> values{0.0, -0.0, 1.0, -1.0, 1e-50, -1e-50, 1e-40, -1e-40, 0.1, -0.1,
                               1.0 / 3, -1.0 / 3, fmax, -fmax, 3.4028235e38, -3.4028235e38,
                               1e39, -1e39, 1e300, -1e300, kInfinity, -kInfinity};
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 2000; ++i) values.push_back(std::ldexp(u(rng), static_cast<int>(rng() % 300) - 150));
    for (double v : values) {
        const float f = static_cast<float>(v);
        const float up = static_cast<double>(f) < v ? std::nextafter(f, finf) : f;
        const float down = static_cast<double>(f) > v ? std::nextafter(f, -finf) : f;
        EXPECT_EQ(float_up(v), up) << v;
        EXPECT_EQ(float_down(v), down) << v;
        EXPECT_GE(static_cast<double>(float_up(v)), v) << v;
        EXPECT_LE(static_cast<double>(float_down(v)), v) << v;
    }
    EXPECT_TRUE(std::isnan(float_up(std::nan(""))));
    EXPECT_TRUE(std::isnan(float_down(std::nan(""))));
}

// offset_ray_origin moves a point strictly off its surface by at least the error bound.
TEST(Float, OffsetRayOriginLeavesTheErrorBox) {
    Vec3 p(1e5, 2, -3), e(1e-11, 1e-16, 1e-16), n(0, 1, 0);
    Vec3 up = offset_ray_origin(p, e, n, {0, 1, 0});
    Vec3 down = offset_ray_origin(p, e, n, {0.3, -1, 0});
    EXPECT_GT(up.y, p.y + e.y);
    EXPECT_LT(down.y, p.y - e.y);
    EXPECT_EQ(up.x, p.x);
}

}  // namespace
}  // namespace glint
