// Copies of declared CSG objects: their children are shared until a copy changes them
// (PovChildren), the copies' transforms still reach every texture below, in order, and parts
// with uniform textures share one material across copies.
#include <gtest/gtest.h>

#include <set>
#include <variant>

#include "pov_test_util.h"

namespace glint::pov {
namespace {

using testing::parse;

const scene::Csg& csg_of(const scene::Object& o) { return std::get<scene::Csg>(o.shape); }

const scene::Pigment& pigment_of(const scene::Scene& s, const scene::Object& o) {
    return s.materials[static_cast<size_t>(o.material)].texture.pigment;
}

TEST(PovCopies, NestedCopiesMoveEveryTextureInOrder) {
    // Each level's transforms reach the leaf's pattern, in the order they were written: the
    // rotation after the translation, so the leaf's pattern origin ends up at (0, 0, -1)
    // for copy 1 of the outer union, not at (1, 0, 0) rotated first.
    auto s = parse(
        "#declare Leaf = sphere { 0, 1 pigment { checker } }\n"
        "#declare Inner = union { object { Leaf } object { Leaf translate 5*y } }\n"
        "#declare Outer = union { object { Inner translate x } object { Inner rotate 90*y } }\n"
        "object { Outer translate 10*z }\n"
        "object { Outer rotate 90*y }\n");
    ASSERT_EQ(s.objects.size(), 2u);
    const auto& outer0 = csg_of(s.objects[0]);
    ASSERT_EQ(outer0.children.size(), 2u);
    const auto& inner0 = csg_of(outer0.children[0]);
    ASSERT_EQ(inner0.children.size(), 2u);
    // Leaf 1 of copy 0 of Inner: translate 5y, translate x, translate 10z.
    const Vec3 p = pigment_of(s, inner0.children[1]).transform.point(Vec3(0, 0, 0));
    EXPECT_NEAR(p.x, 1, 1e-12);
    EXPECT_NEAR(p.y, 5, 1e-12);
    EXPECT_NEAR(p.z, 10, 1e-12);
    // The second placed copy: translate x, then rotate 90 about y sends x to -z.
    const auto& inner1 = csg_of(csg_of(s.objects[1]).children[0]);
    const Vec3 q = pigment_of(s, inner1.children[0]).transform.point(Vec3(0, 0, 0));
    EXPECT_NEAR(q.x, 0, 1e-12);
    EXPECT_NEAR(q.z, -1, 1e-12);
    // The pattern moved, the shape with it (the leaf's own transform is its copy's).
    EXPECT_EQ(inner0.children[1].transform.point(Vec3(0, 0, 0)), Vec3(0, 5, 0));
}

TEST(PovCopies, CopiesTransformedAsEagerlyAsTheyAreParsed) {
    // A texture given after a transform is not moved by it; one given before is, even where
    // the copy's children are shared with the declaration until then.
    auto s = parse(
        "#declare U = union { sphere { 0, 1 pigment { checker } } sphere { x, 1 } }\n"
        "object { U translate y texture { pigment { checker } } translate z }\n"
        "object { U }\n");
    ASSERT_EQ(s.objects.size(), 2u);
    const auto& a = csg_of(s.objects[0]);
    const Vec3 child = pigment_of(s, a.children[0]).transform.point(Vec3(0, 0, 0));
    EXPECT_EQ(child, Vec3(0, 1, 1));
    const Vec3 own = pigment_of(s, s.objects[0]).transform.point(Vec3(0, 0, 0));
    EXPECT_EQ(own, Vec3(0, 0, 1));
    // The declaration itself is untouched by the first copy's transforms.
    const auto& b = csg_of(s.objects[1]);
    EXPECT_EQ(pigment_of(s, b.children[0]).transform.point(Vec3(0, 0, 0)), Vec3(0, 0, 0));
}

TEST(PovCopies, ChangingACopyLeavesTheDeclarationAlone) {
    // A light_group marks the objects of its copy; the declared union's other copy is not in
    // the group.
    auto s = parse(
        "#declare U = union { sphere { 0, 1 pigment { rgb 1 } } sphere { x, 1 } translate y }\n"
        "light_group { light_source { 0, rgb 1 } object { U } }\n"
        "object { U translate x }\n");
    ASSERT_EQ(s.objects.size(), 2u);
    const auto& grouped = csg_of(csg_of(s.objects[0]).children[0]);
    EXPECT_GE(grouped.children[0].light_group, 0);
    const auto& plain = csg_of(s.objects[1]);
    EXPECT_LT(plain.children[0].light_group, 0);
    EXPECT_LT(plain.children[1].light_group, 0);
}

TEST(PovCopies, UniformTexturesShareAMaterialPatternedOnesDoNot) {
    auto s = parse(
        "#declare Part = union {\n"
        "  sphere { 0, 1 pigment { rgb <1, 0, 0> } finish { phong 1 } }\n"
        "  box { 0, 1 pigment { checker } }\n"
        "}\n"
        "union { #for (i, 0, 9) object { Part translate i*x } #end }\n");
    ASSERT_EQ(s.objects.size(), 1u);
    const auto& copies = csg_of(s.objects[0]).children;
    ASSERT_EQ(copies.size(), 10u);
    std::set<int> spheres, boxes;
    for (const auto& c : copies) {
        spheres.insert(csg_of(c).children[0].material);
        boxes.insert(csg_of(c).children[1].material);
    }
    // One material for the ten red spheres; ten for the checkers, each moved with its copy.
    EXPECT_EQ(spheres.size(), 1u);
    EXPECT_EQ(boxes.size(), 10u);
    for (size_t i = 0; i < copies.size(); ++i) {
        const auto& box = csg_of(copies[i]).children[1];
        EXPECT_EQ(pigment_of(s, box).transform.point(Vec3(0, 0, 0)),
                  Vec3(static_cast<double>(i), 0, 0));
    }
    const auto& red = s.materials[static_cast<size_t>(*spheres.begin())].texture;
    EXPECT_EQ(red.pigment.color.rgb, Color(1, 0, 0));
    EXPECT_EQ(red.finish.phong, 1);
}

TEST(PovCopies, SeparatelyPlacedObjectsKeepTheirOwnMaterials) {
    // Top-level objects each start an interior of their own (Material::interior_id), so
    // their materials stay apart even for one declared uniform texture.
    auto s = parse(
        "#declare U = union { sphere { 0, 1 pigment { rgb 1 } } sphere { x, 1 } }\n"
        "object { U }\n"
        "object { U translate y }\n");
    ASSERT_EQ(s.objects.size(), 2u);
    const int a = csg_of(s.objects[0]).children[0].material;
    const int b = csg_of(s.objects[1]).children[0].material;
    EXPECT_NE(a, b);
    EXPECT_NE(s.materials[static_cast<size_t>(a)].interior_id,
              s.materials[static_cast<size_t>(b)].interior_id);
}

}  // namespace
}  // namespace glint::pov
