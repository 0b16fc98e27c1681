// Motion blur: the interpolation of moving transforms (core/motion.h, Cycles 3.4's
// decompose / slerp / compose), the bound of a moving object, moving objects in the scene's
// BVH at a ray's time, and the shutter's camera motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/motion.h"
#include "geom_test_util.h"
#include "render/film/shutter.h"

namespace glint {
namespace {

constexpr double kPi = 3.14159265358979323846;

Matrix4 rot_z(double radians, Vec3 at = {}) {
    Matrix4 m;
    m.m[0][0] = std::cos(radians), m.m[0][1] = -std::sin(radians);
    m.m[1][0] = std::sin(radians), m.m[1][1] = std::cos(radians);
    m.m[0][3] = at.x, m.m[1][3] = at.y, m.m[2][3] = at.z;
    return m;
}

Vec3 apply(const Matrix4& m, const Vec3& p) {
    return {m.m[0][0] * p.x + m.m[0][1] * p.y + m.m[0][2] * p.z + m.m[0][3],
            m.m[1][0] * p.x + m.m[1][1] * p.y + m.m[1][2] * p.z + m.m[1][3],
            m.m[2][0] * p.x + m.m[2][1] * p.y + m.m[2][2] * p.z + m.m[2][3]};
}

void expect_matrix_near(const Matrix4& a, const Matrix4& b, double tol) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(a.m[i][j], b.m[i][j], tol) << i << "," << j;
}

TEST(Motion, DecomposeComposeRoundTrip) {
    // Rotation, non-uniform scale, shear, a mirror and a translation.
    Matrix4 m = rot_z(0.7, {1, -2, 3});
    Matrix4 s;
    s.m[0][0] = 2, s.m[0][1] = 0.3, s.m[1][1] = -0.5, s.m[2][2] = 1.5, s.m[2][0] = 0.2;
    m = m * s;
    expect_matrix_near(compose(decompose(m)), m, 1e-12);
    const DecomposedTransform d = decompose(m);
    EXPECT_NEAR(d.q[0] * d.q[0] + d.q[1] * d.q[1] + d.q[2] * d.q[2] + d.q[3] * d.q[3], 1, 1e-12);
}

TEST(Motion, RotationInterpolatesItsAngle) {
    // 0 -> 170 degrees about Z in one step: slerp turns at a constant rate, so t = 0.5 is 85
    // degrees (a linear blend of the matrices would shrink the object instead).
    const MotionTransform two({rot_z(0), rot_z(170 * kPi / 180)});
    const Matrix4 half = two.matrix_at(0.5);
    EXPECT_NEAR(std::atan2(half.m[1][0], half.m[0][0]) * 180 / kPi, 85, 1e-9);
    EXPECT_NEAR(std::hypot(half.m[0][0], half.m[1][0]), 1, 1e-12);  // no shrinking
    const Matrix4 quarter = two.matrix_at(0.25);
    EXPECT_NEAR(std::atan2(quarter.m[1][0], quarter.m[0][0]) * 180 / kPi, 42.5, 1e-9);
    // Three steps (Cycles' default), 0, 45, 90 degrees: the middle step is met exactly and
    // t = 0.75 is 67.5 degrees.
    const MotionTransform three({rot_z(0), rot_z(kPi / 4), rot_z(kPi / 2)});
    expect_matrix_near(three.matrix_at(0.5), rot_z(kPi / 4), 1e-12);
    const Matrix4 m = three.matrix_at(0.75);
    EXPECT_NEAR(std::atan2(m.m[1][0], m.m[0][0]) * 180 / kPi, 67.5, 1e-9);
    // The ends are the steps.
    expect_matrix_near(three.matrix_at(0), rot_z(0), 1e-12);
    expect_matrix_near(three.matrix_at(1), rot_z(kPi / 2), 1e-12);
}

TEST(Motion, ShortWayRoundAndTranslationScale) {
    // 350 degrees is -10: the quaternions are put in one hemisphere, so halfway is -5.
    const MotionTransform mt({rot_z(0, {0, 0, 0}), rot_z(350 * kPi / 180, {4, 0, 0})});
    const Matrix4 m = mt.matrix_at(0.5);
    EXPECT_NEAR(std::atan2(m.m[1][0], m.m[0][0]) * 180 / kPi, -5, 1e-9);
    EXPECT_NEAR(m.m[0][3], 2, 1e-12);
    // Scale blends linearly: 1 -> 3 is 2 at the middle.
    Matrix4 big;
    big.m[0][0] = big.m[1][1] = big.m[2][2] = 3;
    const Matrix4 s = MotionTransform({Matrix4{}, big}).matrix_at(0.5);
    EXPECT_NEAR(s.m[0][0], 2, 1e-12);
    EXPECT_NEAR(s.m[2][2], 2, 1e-12);
}

TEST(Motion, BoundsHoldTheSweptBox) {
    // A box off the rotation axis, turning half a circle while moving and growing: the
    // union of the boxes at the steps misses most of its arc.
    Matrix4 grow;
    grow.m[0][0] = grow.m[1][1] = grow.m[2][2] = 1.5;
    const std::vector<Matrix4> steps = {rot_z(0, {0, 0, 0}), rot_z(kPi / 2, {1, 0, 0}) * grow,
                                        rot_z(kPi, {2, 1, 0})};
    const MotionTransform mt(steps);
    const Bounds3 local{{2, -0.5, -0.5}, {3, 0.5, 0.5}};
    const Bounds3 b = mt.bounds(local);
    Bounds3 swept;
    for (int k = 0; k <= 20000; ++k) {
        const Matrix4 m = mt.matrix_at(k / 20000.0);
        for (int c = 0; c < 8; ++c) {
            const Vec3 p{(c & 1) ? local.hi.x : local.lo.x, (c & 2) ? local.hi.y : local.lo.y,
                         (c & 4) ? local.hi.z : local.lo.z};
            const Vec3 q = apply(m, p);
            swept.extend(q);
            ASSERT_GE(q.x, b.lo.x);
            ASSERT_GE(q.y, b.lo.y);
            ASSERT_GE(q.z, b.lo.z);
            ASSERT_LE(q.x, b.hi.x);
            ASSERT_LE(q.y, b.hi.y);
            ASSERT_LE(q.z, b.hi.z);
        }
    }
    // Conservative but not loose: past the sweep by at most 5% of its largest extent on
    // each side (the padding is the same on every axis).
    const Vec3 extent = swept.hi - swept.lo;
    const double largest = std::max({extent.x, extent.y, extent.z});
    for (int a = 0; a < 3; ++a) {
        EXPECT_LT(swept.lo[a] - b.lo[a], 0.05 * largest) << "axis " << a;
        EXPECT_LT(b.hi[a] - swept.hi[a], 0.05 * largest) << "axis " << a;
    }
    // The union of the boxes at the steps alone would not hold it (the arc bulges to -x).
    Bounds3 at_steps;
    for (const Matrix4& m : steps) at_steps.extend(Transform(m, Matrix4{}).bounds(local));
    EXPECT_LT(swept.lo.x, at_steps.lo.x - 0.3);
}

// A unit cube mesh moving from x = -3 to x = +3 over the shutter, and a still one far away
// (so the scene's BVH has two leaves).
scene::Scene moving_cube_scene() {
    scene::Scene s;
    s.materials.resize(2);
    s.meshes.push_back(test::unit_cube_mesh({-0.5, -0.5, -0.5}));
    scene::Object moving = test::object(scene::MeshRef{0});
    moving.motion = {Transform::translate({-3, 0, 0}).matrix(), Matrix4{},
                     Transform::translate({3, 0, 0}).matrix()};
    s.objects.push_back(moving);
    s.objects.push_back(test::object(scene::MeshRef{0}, Transform::translate({0, 50, 0}), 1));
    return s;
}

TEST(Motion, MovingObjectIsMetAtTheRaysTime) {
    const scene::Scene s = moving_cube_scene();
    auto g = test::build(s);
    // The scene's box holds the whole sweep.
    EXPECT_LE(g->bounds().lo.x, -3.5);
    EXPECT_GE(g->bounds().hi.x, 3.5);
    for (double time : {0.0, 0.25, 0.5, 0.8, 1.0}) {
        const double x = -3 + 6 * time;
        // The same cube standing still where the moving one is at `time`.
        std::vector<scene::Object> still_objects;
        still_objects.push_back(test::object(scene::MeshRef{0}, Transform::translate({x, 0, 0})));
        scene::Scene still = test::scene_of(std::move(still_objects));
        still.meshes = s.meshes;
        render::Ray r = test::ray({x + 0.2, 0.1, -10}, {0.01, 0, 1});
        render::Hit want;
        ASSERT_TRUE(test::build(still)->intersect(r, &want));
        r.time = time;
        render::Hit h;
        ASSERT_TRUE(g->intersect(r, &h)) << time;
        EXPECT_NEAR(h.t, want.t, 1e-12);
        EXPECT_NEAR(h.p.x, want.p.x, 1e-12);
        EXPECT_NEAR(h.ng.z, want.ng.z, 1e-12);
        EXPECT_NEAR(std::fabs(h.ng.z), 1, 1e-12);
        EXPECT_EQ(h.object, 0);
        EXPECT_TRUE(g->occluded(r));
        // Where the cube was at another time there is nothing now.
        render::Ray away = test::ray({x + 2, 0, -10}, {0, 0, 1});
        away.time = time;
        EXPECT_FALSE(g->intersect(away, &h)) << time;
        EXPECT_FALSE(g->occluded(away)) << time;
    }
    // A ray of the default time (0.5, scenes without motion blur) sees it at the frame.
    render::Hit h;
    ASSERT_TRUE(g->intersect(test::ray({0, 0, -10}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.p.x, 0, 1e-12);
}

// A deforming mesh (scene::Mesh::motion_positions): 3 steps sliding the cube along x and
// raising its top; at each time a ray meets the faces of the vertices interpolated between
// the two steps about it, exactly as a still copy of that interpolated mesh.
TEST(Motion, DeformingMeshIsMetAtTheRaysTime) {
    scene::Scene s;
    s.materials.resize(1);
    scene::Mesh m = test::unit_cube_mesh({-0.5, -0.5, -0.5});
    auto step = [&](double dx, double lift) {
        std::vector<Vec3> p = m.positions;
        for (Vec3& v : p) v = {v.x + dx, v.y, v.z > 0 ? v.z + lift : v.z};
        return p;
    };
    m.motion_positions = {step(-3, 0), step(0, 1), step(3, 3)};
    s.meshes.push_back(m);
    s.objects.push_back(test::object(scene::MeshRef{0}));
    auto g = test::build(s);
    EXPECT_LE(g->bounds().lo.x, -3.5);
    EXPECT_GE(g->bounds().hi.x, 3.5);
    EXPECT_GE(g->bounds().hi.z, 3.5);
    for (double time : {0.0, 0.25, 0.5, 0.7, 1.0}) {
        const double s_at = time * 2;
        const size_t k = std::min<size_t>(static_cast<size_t>(s_at), 1);
        const double f = s_at - static_cast<double>(k);
        scene::Mesh at = m;
        at.motion_positions.clear();
        for (size_t i = 0; i < at.positions.size(); ++i)
            at.positions[i] = m.motion_positions[k][i] +
                              (m.motion_positions[k + 1][i] - m.motion_positions[k][i]) * f;
        std::vector<scene::Object> one;
        one.push_back(test::object(scene::MeshRef{0}));
        scene::Scene still = test::scene_of(std::move(one));
        still.meshes = {at};
        const double x = -3 + 6 * time;
        // From above, onto the raised top, and from the side.
        for (const auto& [o, d] : {std::pair{Vec3{x + 0.1, 0.2, 10}, Vec3{0.02, 0, -1}},
                                   std::pair{Vec3{x - 10, 0.1, 0.2}, Vec3{1, 0.01, 0}}}) {
            render::Ray r = test::ray(o, d);
            render::Hit want;
            ASSERT_TRUE(test::build(still)->intersect(r, &want)) << time;
            r.time = time;
            render::Hit h;
            ASSERT_TRUE(g->intersect(r, &h)) << time;
            // (The still mesh keeps its vertices in single precision, the deforming one in
            // double.)
            EXPECT_NEAR(h.t, want.t, 1e-6) << time;
            EXPECT_NEAR(h.p.z, want.p.z, 1e-6) << time;
            EXPECT_NEAR(dot(h.ng, want.ng), 1, 1e-12) << time;
            EXPECT_TRUE(g->occluded(r)) << time;
        }
        // Where the cube is at other times there is nothing now.
        render::Ray away = test::ray({x + 2.2, 0, 10}, {0, 0, -1});
        away.time = time;
        render::Hit h;
        EXPECT_FALSE(g->intersect(away, &h)) << time;
        EXPECT_FALSE(g->occluded(away)) << time;
    }
}

TEST(Motion, ShutterMovesTheCameraRay) {
    scene::Scene s;
    // The camera at the frame at the origin; it moves +2 in x and turns 90 degrees about Z
    // over the shutter.
    s.camera.centre = rot_z(kPi / 4, {1, 0, 0});
    s.camera.motion = {rot_z(0, {0, 0, 0}), rot_z(kPi / 4, {1, 0, 0}), rot_z(kPi / 2, {2, 0, 0})};
    const render::Shutter shutter(s);
    ASSERT_TRUE(shutter.active());
    // A ray the camera at the frame makes: from its location along its +x axis.
    const Vec3 x_axis = normalize(Vec3(1, 1, 0));
    render::Ray r = test::ray({1, 0, 0}, x_axis);
    shutter.expose(0.0, &r);
    EXPECT_EQ(r.time, 0.0);
    EXPECT_NEAR(r.origin.x, 0, 1e-12);
    EXPECT_NEAR(r.dir.x, 1, 1e-12);  // the camera's x axis at the start
    render::Ray e = test::ray({1, 0, 0}, x_axis);
    shutter.expose(1.0, &e);
    EXPECT_NEAR(e.origin.x, 2, 1e-12);
    EXPECT_NEAR(e.dir.y, 1, 1e-12);
    // A scene without motion has an inactive shutter; a deforming mesh alone opens it (the
    // add-on's scene of one armature-bent mesh rendered sharp before).
    EXPECT_FALSE(render::Shutter(scene::Scene{}).active());
    scene::Scene deforming;
    deforming.meshes.push_back(test::unit_cube_mesh());
    EXPECT_FALSE(render::Shutter(deforming).active());
    deforming.meshes[0].motion_positions = {deforming.meshes[0].positions,
                                            deforming.meshes[0].positions};
    EXPECT_TRUE(render::Shutter(deforming).active());
}

}  // namespace
}  // namespace glint
