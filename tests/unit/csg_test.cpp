// CSG (POV-Ray 3.7 manual 2.4.4): union, merge, intersection, difference, inverse, and
// clipped_by / bounded_by, through build_geometry().
#include <gtest/gtest.h>

#include <cmath>

#include "geom_test_util.h"

namespace glint {
namespace {

using render::Hit;
using test::build;
using test::object;
using test::ray;
using test::scene_of;
using test::unit_cube_mesh;

scene::Object csg(scene::CsgOp op, std::vector<scene::Object> children, int material = 0) {
    scene::Csg c;
    c.op = op;
    c.children = std::move(children);
    return object(std::move(c), {}, material);
}

scene::Object sphere(Vec3 c, double r, int material = -1) {
    return object(scene::Sphere{c, r}, {}, material);
}

scene::Object box(Vec3 a, Vec3 b, int material = -1) {
    return object(scene::Box{a, b}, {}, material);
}

scene::Object plane(Vec3 n, double d) { return object(scene::Plane{n, d}, {}, -1); }

scene::Object quadric(Vec3 square, double constant, Transform xf = {}) {
    scene::Quadric q;
    q.square = square;
    q.constant = constant;
    return object(q, xf, -1);
}

// shapes.inc's Cylinder_Y and Hyperboloid_Y cut by planes, as POV-Ray's chess pieces are: the
// intersection is finite (POV-Ray's bounding boxes find it too), and still hit where it was.
TEST(Csg, QuadricsBetweenPlanesAreBounded) {
    const Transform wide = Transform::scale({2, 1, 2});
    auto g = build(scene_of({csg(scene::CsgOp::Intersection,
                                 {quadric({1, 0, 1}, -1, wide), plane({0, 1, 0}, 3),
                                  plane({0, -1, 0}, 1)})}));
    const Bounds3 b = g->finite_bounds();
    ASSERT_FALSE(b.empty());
    EXPECT_NEAR(b.lo.x, -2, 1e-6);
    EXPECT_NEAR(b.hi.x, 2, 1e-6);
    EXPECT_NEAR(b.lo.y, -1, 1e-6);
    EXPECT_NEAR(b.hi.y, 3, 1e-6);
    EXPECT_NEAR(b.hi.z, 2, 1e-6);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({-5, 0, 0}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 3, 1e-9);
    ASSERT_TRUE(g->intersect(ray({0, 10, 0}, {0, -1, 0}), &h));
    EXPECT_NEAR(h.t, 7, 1e-9);
    // A hyperboloid of one sheet between y = 0 and y = 2: |x| <= sqrt(1 + 2^2).
    auto hyp = build(scene_of({csg(scene::CsgOp::Intersection,
                                   {quadric({1, -1, 1}, -1), plane({0, 1, 0}, 2),
                                    plane({0, -1, 0}, 0)})}));
    const Bounds3 hb = hyp->finite_bounds();
    ASSERT_FALSE(hb.empty());
    EXPECT_NEAR(hb.hi.x, std::sqrt(5.0), 1e-6);
    EXPECT_NEAR(hb.lo.z, -std::sqrt(5.0), 1e-6);
    ASSERT_TRUE(hyp->intersect(ray({-5, 2 - 1e-9, 0}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 5 - std::sqrt(5.0), 1e-6);
    // A rotated plane bounds nothing: the intersection stays unbounded.
    auto open = build(scene_of({csg(scene::CsgOp::Intersection,
                                    {quadric({1, 0, 1}, -1), plane({0, 1, 1}, 3)})}));
    EXPECT_TRUE(open->finite_bounds().empty());
}

TEST(Csg, HalfSpacesKeepTheirSideUnderAxisTransforms) {
    const Bounds3 half{Vec3(-kInfinity, -kInfinity, -kInfinity), Vec3(kInfinity, 2, kInfinity)};
    const Bounds3 b = Transform::scale({1, -3, 1}).then(Transform::translate({0, 1, 0})).bounds(half);
    EXPECT_NEAR(b.lo.y, -5, 1e-9);
    EXPECT_TRUE(std::isinf(b.hi.y));
    EXPECT_TRUE(std::isinf(b.lo.x));
    const Bounds3 r = Transform::rotate_xyz_degrees({0, 0, 30}).bounds(half);
    EXPECT_TRUE(std::isinf(r.hi.y));
}

// Sphere A at the origin minus sphere B at x = 1: the solid is the part of A left of B.
TEST(Csg, DifferenceOfTwoSpheres) {
    auto g = build(scene_of({csg(scene::CsgOp::Difference,
                                 {sphere({0, 0, 0}, 1, 1), sphere({1, 0, 0}, 1, 2)})}));
    Hit h;
    ASSERT_TRUE(g->intersect(ray({-5, 0, 0}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 4, 1e-14);
    EXPECT_EQ(h.material, 1);
    // From the right the ray passes B's removed volume and meets B's surface inside A at x = 0;
    // the cutting surface's normal is flipped to point out of the remaining solid (+x).
    ASSERT_TRUE(g->intersect(ray({5, 0, 0}, {-1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 5, 1e-14);
    EXPECT_NEAR(h.ng.x, 1, 1e-14);
    EXPECT_NEAR(h.n.x, 1, 1e-14);
    EXPECT_EQ(h.material, 2);
    // Far off the overlap: only A's left cap remains, the rest of B is never hit.
    EXPECT_FALSE(g->intersect(ray({1.5, 5, 0}, {0, -1, 0}), &h));
    // At x = 0.6 the column through A lies inside B (A: |y| <= 0.8, B: |y| <= 0.917).
    EXPECT_FALSE(g->intersect(ray({0.6, 5, 0}, {0, -1, 0}), &h));
    // At x = -0.5 it is untouched: enters at y = sqrt(0.75).
    ASSERT_TRUE(g->intersect(ray({-0.5, 5, 0}, {0, -1, 0}), &h));
    EXPECT_NEAR(h.t, 5 - std::sqrt(0.75), 1e-14);
}

TEST(Csg, IntersectionOfBoxes) {
    auto g = build(scene_of({csg(scene::CsgOp::Intersection,
                                 {box({-1, -1, -1}, {1, 1, 1}), box({0, 0, 0}, {2, 2, 2})})}));
    Hit h;
    ASSERT_TRUE(g->intersect(ray({-5, 0.5, 0.5}, {1, 0, 0}), &h));
    EXPECT_EQ(h.t, 5);
    EXPECT_EQ(h.ng, Vec3(-1, 0, 0));
    ASSERT_TRUE(g->intersect(ray({5, 0.5, 0.5}, {-1, 0, 0}), &h));
    EXPECT_EQ(h.t, 4);
    EXPECT_EQ(h.ng, Vec3(1, 0, 0));
    EXPECT_FALSE(g->intersect(ray({-5, -0.5, 0.5}, {1, 0, 0}), &h));
    // The bounds are the overlap.
    EXPECT_EQ(g->bounds().lo, Vec3(0, 0, 0));
    EXPECT_EQ(g->bounds().hi, Vec3(1, 1, 1));
}

TEST(Csg, InverseFlipsNormalsAndInside) {
    auto s = scene_of({sphere({0, 0, 0}, 1, 0)});
    s.objects[0].inverse = true;
    auto g = build(s);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 4, 1e-14);
    EXPECT_NEAR(h.ng.z, 1, 1e-14);  // points into the sphere: out of the inverse solid
    EXPECT_TRUE(std::isinf(g->bounds().hi.x));
    // Intersection of a box with an inverse sphere: a box with a spherical hole.
    scene::Object hole = sphere({0, 0, 0}, 0.5);
    hole.inverse = true;
    g = build(scene_of({csg(scene::CsgOp::Intersection, {box({-1, -1, -1}, {1, 1, 1}), hole})}));
    ASSERT_TRUE(g->intersect(ray({0, 0, 0}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 0.5, 1e-14);
    EXPECT_NEAR(h.ng.z, -1, 1e-14);
}

// POV-Ray inverts a CSG by De Morgan (CSG::Invert and Morph): an inverted union is the
// intersection of its inverted children, so the inner walls a union keeps are gone from its
// complement. Two overlapping spheres cut from a box: from inside the overlap the first
// surface is the far side of the pair, not sphere B's wall inside sphere A.
TEST(Csg, InverseUnionIsTheIntersectionOfInvertedChildren) {
    scene::Object pair = csg(scene::CsgOp::Union, {sphere({0, 0, 0}, 1), sphere({1, 0, 0}, 1)});
    pair.inverse = true;
    auto g = build(scene_of({csg(scene::CsgOp::Intersection,
                                 {box({-3, -3, -3}, {3, 3, 3}), pair})}));
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0.5, 0, 0}, {-1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 1.5, 1e-14);
    EXPECT_NEAR(h.ng.x, 1, 1e-14);  // facing into the hole, out of the solid
    // An inverted difference is the merge of the inverted first child and the others: from
    // inside sphere B (outside A - B), the first surface along +x is B's far side.
    scene::Object cut =
        csg(scene::CsgOp::Difference, {sphere({0, 0, 0}, 1), sphere({1, 0, 0}, 1)});
    cut.inverse = true;
    g = build(scene_of({csg(scene::CsgOp::Intersection, {box({-3, -3, -3}, {3, 3, 3}), cut})}));
    ASSERT_TRUE(g->intersect(ray({-5, 0, 0}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 2, 1e-14);  // the box's face: outside A is solid
    ASSERT_TRUE(g->intersect(ray({-0.5, 0, 0}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 0.5, 1e-14);  // A - B's boundary at x = 0, B's surface
    EXPECT_NEAR(h.ng.x, -1, 1e-14);
}

TEST(Csg, MergeRemovesInternalSurfacesUnionKeepsThem) {
    std::vector<scene::Object> two = {sphere({0, 0, 0}, 1), sphere({1, 0, 0}, 1)};
    auto u = build(scene_of({csg(scene::CsgOp::Union, two)}));
    auto m = build(scene_of({csg(scene::CsgOp::Merge, two)}));
    Hit h;
    // From inside the overlap going -x: the union meets B's surface at x = 0 first.
    ASSERT_TRUE(u->intersect(ray({0.5, 0, 0}, {-1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 0.5, 1e-14);
    ASSERT_TRUE(m->intersect(ray({0.5, 0, 0}, {-1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 1.5, 1e-14);
    EXPECT_NEAR(h.ng.x, -1, 1e-14);
}

TEST(Csg, MaterialInheritanceAndFlags) {
    auto s = scene_of({csg(scene::CsgOp::Union, {sphere({0, 0, 0}, 1), sphere({0, 0, 5}, 1, 3)}, 2)});
    s.objects[0].no_shadow = true;
    s.objects[0].double_illuminate = true;
    auto g = build(s);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
    EXPECT_EQ(h.material, 2);  // inherited from the union
    EXPECT_EQ(h.flags, render::kNoShadow | render::kDoubleIlluminate);
    ASSERT_TRUE(g->intersect(ray({0, 0, 3}, {0, 0, 1}), &h));
    EXPECT_EQ(h.material, 3);  // its own
    EXPECT_FALSE(g->occluded(ray({0, 0, -5}, {0, 0, 1})));
}

// Regression: a nearer child tested after a farther one must not keep the farther one's
// material (its own is -1: the union's).
TEST(Csg, UnionChildDoesNotInheritSiblingMaterial) {
    for (int n : {2, 6}) {  // linear search and the union's own BVH
        std::vector<scene::Object> kids = {sphere({0, 0, 5}, 1, 3)};
        for (int i = 1; i < n; ++i) kids.push_back(sphere({0, 0, -3.0 * i + 3}, 0.5));
        auto g = build(scene_of({csg(scene::CsgOp::Union, kids, 2)}));
        Hit h;
        ASSERT_TRUE(g->intersect(ray({0, 0, -30}, {0, 0, 1}), &h));
        EXPECT_EQ(h.material, 2) << n;
        ASSERT_TRUE(g->intersect(ray({0, 0, 3.5}, {0, 0, 1}), &h));
        EXPECT_EQ(h.material, 3) << n;
    }
}

TEST(Csg, NoShadowChildStillShapesTheResult) {
    scene::Object cutter = sphere({1, 0, 0}, 1);
    cutter.no_shadow = true;
    auto g = build(scene_of({csg(scene::CsgOp::Difference, {sphere({0, 0, 0}, 1), cutter})}));
    // The cut surface belongs to the no_shadow child: a shadow ray through it from the right
    // meets nothing else that casts shadows until A's left side.
    EXPECT_TRUE(g->occluded(ray({5, 0, 0}, {-1, 0, 0})));
    Hit h;
    ASSERT_TRUE(g->intersect(ray({5, 0, 0}, {-1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 5, 1e-14);
    EXPECT_FALSE(g->occluded(ray({5, 0, 0}, {-1, 0, 0}, 5.5)));
}

TEST(Csg, ClippedByKeepsSurfaceInsideClip) {
    scene::Object s = sphere({0, 0, 0}, 1, 0);
    s.clipped_by.push_back(object(scene::Plane{{0, 1, 0}, 0}));  // keep y < 0
    auto g = build(scene_of({s}));
    Hit h;
    // The top half is gone: the ray meets the inside of the bottom half.
    ASSERT_TRUE(g->intersect(ray({0, 5, 0}, {0, -1, 0}), &h));
    EXPECT_NEAR(h.t, 6, 1e-14);
    EXPECT_NEAR(h.ng.y, -1, 1e-14);
    EXPECT_LE(g->bounds().hi.y, 1.0 + 1e-12);
}

TEST(Csg, BoundedByMissMeansNoHit) {
    scene::Object s = sphere({0, 0, 0}, 1, 0);
    s.bounded_by.push_back(box({-2, -2, -2}, {2, 0.5, 2}));
    auto g = build(scene_of({s}));
    Hit h;
    EXPECT_TRUE(g->intersect(ray({0, 5, 0}, {0, -1, 0}), &h));  // passes the bound lower down
    // POV-Ray semantics: a ray that misses the bound misses the object, even where the object
    // pokes out of it.
    EXPECT_FALSE(g->intersect(ray({-5, 0.9, 0}, {1, 0, 0}), &h));
    EXPECT_TRUE(g->intersect(ray({-5, 0.1, 0}, {1, 0, 0}), &h));
}

// A cutter with more hits along the ray than the inline hit buffer holds.
TEST(Csg, ManyHitsAlongOneRay) {
    std::vector<scene::Object> row;
    for (int i = 0; i < 6; ++i) row.push_back(sphere({-2.5 + i, 0, 0}, 0.3));
    auto g = build(scene_of({csg(scene::CsgOp::Difference,
                                 {box({-3, -1, -1}, {3, 1, 1}), csg(scene::CsgOp::Union, row)})}));
    Hit h;
    ASSERT_TRUE(g->intersect(ray({-2.0, 0, 0}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 0.2, 1e-14);
    EXPECT_NEAR(h.ng.x, 1, 1e-14);
    ASSERT_TRUE(g->intersect(ray({-1.0, 0, 0}, {-1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 0.2, 1e-14);
    EXPECT_NEAR(h.ng.x, -1, 1e-14);
    // Through the hole of the last sphere to the box's far face.
    ASSERT_TRUE(g->intersect(ray({2.9, 0, 0}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 0.1, 1e-14);
}

TEST(Csg, NestedTransformsCompose) {
    scene::Object inner = sphere({0, 0, 0}, 1);
    inner.transform = Transform::translate({2, 0, 0});
    scene::Object u = csg(scene::CsgOp::Union, {inner}, 1);
    u.transform = Transform::scale({2, 2, 2}).then(Transform::translate({0, 0, 10}));
    auto g = build(scene_of({u}));
    Hit h;
    ASSERT_TRUE(g->intersect(ray({4, 0, 0}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 8, 1e-13);
    EXPECT_NEAR(h.ng.z, -1, 1e-13);
}

TEST(Csg, DifferenceWithMeshInsideVector) {
    // A box minus a closed mesh cube (inside by parity along inside_vector).
    scene::Scene s;
    s.materials.resize(2);
    scene::Mesh m = unit_cube_mesh({-0.5, -0.5, -0.5});
    m.has_inside_vector = true;
    m.inside_vector = {0.1, 0.2, 1};
    s.meshes.push_back(m);
    s.objects.push_back(
        csg(scene::CsgOp::Difference, {box({-1, -1, -1}, {1, 1, 1}), object(scene::MeshRef{0}, {}, -1)}));
    auto g = build(s);
    Hit h;
    // From the centre (inside the removed cube) the first surviving surface is the cube's face.
    ASSERT_TRUE(g->intersect(ray({0.1, 0.05, 0}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 0.4, 1e-14);
    EXPECT_NEAR(std::fabs(h.ng.x), 1, 1e-14);
}

}  // namespace
}  // namespace glint
