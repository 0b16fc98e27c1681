// POV-Ray's object-level `uv_mapping` (the object's UV_FLAG): every texture of the object is
// evaluated at (u, v, 0), the object's later transforms leave its textures alone, CSG
// children that inherit the texture inherit the mapping, and it must come before the
// texture. Shapes without a uv of their own give the world point's x and y; mesh faces
// without uv_vectors (0, 0).
#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "core/log.h"
#include "render/render.h"
#include "unit/pov_test_util.h"
#include "unit/render_test_util.h"

namespace glint::render {
namespace {

using pov::testing::error_of;
using pov::testing::parse;

Image render_text(const std::string& text) { return test::render_pov(text); }

// Looking down -z at the unit sphere: ambient-only, so the pixel is the pigment.
std::string sphere_scene(const std::string& mods) {
    return "#version 3.7;\n"
           "camera { orthographic location <0, 0, -5> look_at 0 right 2*x up 2*y }\n"
           "sphere { 0, 1 " +
           mods + " }\n";
}

TEST(ObjectUvMapping, TexturesSeeTheSurfacesUv) {
    // The sphere's front at -z is u = 0.75 (Sphere::UVCoord); gradient x reads u.
    const std::string tex = "texture { pigment { gradient x } finish { ambient 1 diffuse 0 } }";
    const Image img = render_text(sphere_scene("uv_mapping " + tex));
    // Pixel (20, 20) is at x = 0.025 on the sphere: u just past 0.75.
    EXPECT_NEAR(img.pixel(20, 20)[0], 0.754, 0.003);
    // Without uv_mapping the same pigment reads the point's x.
    const Image plain = render_text(sphere_scene(tex));
    EXPECT_NEAR(plain.pixel(20, 20)[0], 0.025, 0.003);
    // The object's transforms after uv_mapping do not move its texture in uv space.
    const Image moved = render_text(sphere_scene("uv_mapping " + tex + " scale 0.999 rotate y*0"));
    EXPECT_NEAR(moved.pixel(20, 20)[0], img.pixel(20, 20)[0], 1e-4);
}

TEST(ObjectUvMapping, ObjectTransformsLeaveTheTextureAlone) {
    auto s = parse("sphere { 0, 1 uv_mapping pigment { checker scale 0.1 } translate x scale 2 }");
    const scene::Material& m = s.materials[static_cast<size_t>(s.objects[0].material)];
    EXPECT_TRUE(m.uv_points);
    // Only the pigment's own scale: the object's translate and scale did not reach it.
    EXPECT_NEAR(m.texture.pigment.transform.inverse_point(Vec3(1, 0, 0)).x, 10, 1e-12);
    auto t = parse("sphere { 0, 1 pigment { checker scale 0.1 } translate x }");
    EXPECT_NEAR(t.materials[static_cast<size_t>(t.objects[0].material)]
                    .texture.pigment.transform.inverse_point(Vec3(1, 0, 0)).x,
                0, 1e-12);
}

TEST(ObjectUvMapping, ChildrenThatInheritTheTextureInheritTheMapping) {
    auto s = parse(
        "union { box { 0, 1 } sphere { 0, 1 pigment { rgb 1 } } uv_mapping pigment { checker } }");
    const auto& csg = std::get<scene::Csg>(s.objects[0].shape);
    ASSERT_EQ(csg.children.size(), 2u);
    EXPECT_TRUE(s.materials[static_cast<size_t>(s.objects[0].material)].uv_points);
    EXPECT_EQ(csg.children[0].material, -1);  // the union's material, mapping included
    ASSERT_GE(csg.children[1].material, 0);
    EXPECT_FALSE(s.materials[static_cast<size_t>(csg.children[1].material)].uv_points);
}

TEST(ObjectUvMapping, MustComeBeforeTheTexture) {
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { rgb 1 } uv_mapping }"),
              "1:33: uv_mapping must come before the object's texture");
}

TEST(UvMapping, ShapesWithoutUvUseTheWorldXAndY) {
    // A plane seen from above: uv_mapping reads (x, y, 0) of the world point, so gradient z
    // is 0 everywhere (it varies along the floor's z without uv_mapping).
    const std::string head =
        "#version 3.7;\n"
        "camera { orthographic location <0, 5, 0> look_at 0 right 2*x up 2*z }\n"
        "plane { y, 0 finish { ambient 1 diffuse 0 } pigment { ";
    const Image uv = render_text(head + "uv_mapping gradient z } }");
    const Image world = render_text(head + "gradient z } }");
    EXPECT_FLOAT_EQ(uv.pixel(20, 10)[0], 0.0f);
    EXPECT_FLOAT_EQ(uv.pixel(20, 15)[0], 0.0f);
    EXPECT_NE(world.pixel(20, 10)[0], world.pixel(20, 15)[0]);
}

TEST(UvMapping, MeshFacesWithoutUvVectorsAreAtTheOrigin) {
    // POV-Ray gives a mesh triangle without uv_vectors the uv (0, 0) at every corner, not the
    // world x, y: gradient x under uv_mapping reads 0 across the left face, while the right
    // face's uv_vectors run u from 0 to 1 over it.
    const std::string scene =
        "#version 3.7;\n"
        "camera { orthographic location <0, 0, -5> look_at 0 right 4*x up 4*y }\n"
        "mesh { triangle { <-2, -2, 0>, <0, -2, 0>, <0, 2, 0> }\n"
        "       triangle { <0, -2, 0>, <2, -2, 0>, <2, 2, 0> uv_vectors <0, 0>, <1, 0>, <1, 0> }\n"
        "       uv_mapping pigment { gradient x } finish { ambient 1 diffuse 0 } }\n";
    const Image img = render_text(scene);
    EXPECT_FLOAT_EQ(img.pixel(5, 35)[0], 0.0f);   // x = -1.5
    EXPECT_FLOAT_EQ(img.pixel(15, 35)[0], 0.0f);  // x = -0.5 (world x would be 0.5)
    EXPECT_NEAR(img.pixel(25, 35)[0], 0.25f, 0.03f);  // x = 0.5: u = 0.25
    EXPECT_NEAR(img.pixel(35, 35)[0], 0.75f, 0.03f);  // x = 1.5: u = 0.75
}

}  // namespace
}  // namespace glint::render
