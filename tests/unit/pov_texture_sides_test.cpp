// Two POV-Ray texture features that choose a whole texture per hit: interior_texture (the
// texture of a surface seen from inside, POV-Ray's trace.cpp) and material_map (an image's
// pixels choosing among textures, imageutil.cpp material_map). Parsed into the IR, then
// shaded one ray at a time by the classic renderer with ambient-only finishes, so each
// texture's pigment comes back exactly.
#include <gtest/gtest.h>

#include <png.h>

#include <cstdio>
#include <filesystem>

#include "core/log.h"
#include "render/integrators/whitted.h"
#include "render/prepare/prepared_scene.h"
#include "render/textures/pigment.h"
#include "unit/pov_test_util.h"

namespace glint {
namespace {

using pov::testing::error_of;
using pov::testing::parse;

// Renders one ray of a scene with the classic renderer.
Color trace(const scene::Scene& s, Vec3 origin, Vec3 dir) {
    Diagnostics diag;
    render::RenderOptions opts;
    auto prepared = render::prepare(s, opts, diag);
    render::Whitted w(*prepared);
    render::Ray r;
    r.origin = origin;
    r.dir = normalize(dir);
    return w.li(r);
}

// A pigment that shows as itself: full ambient, no diffuse.
std::string lit(const std::string& rgb) {
    return "pigment { rgb " + rgb + " } finish { ambient 1 diffuse 0 }";
}

TEST(InteriorTexture, ParsedIntoTheMaterialAndMovedWithTheObject) {
    auto s = parse("sphere { 0, 1 texture { " + lit("<1, 0, 0>") + " } interior_texture { " +
                   lit("<0, 1, 0>") + " } translate <1, 2, 3> }");
    ASSERT_EQ(s.objects.size(), 1u);
    const scene::Material& m = s.materials[static_cast<size_t>(s.objects[0].material)];
    ASSERT_EQ(m.interior_texture.size(), 1u);
    EXPECT_EQ(m.interior_texture[0].pigment.color.rgb, Color(0, 1, 0));
    EXPECT_EQ(m.texture.pigment.color.rgb, Color(1, 0, 0));
    EXPECT_EQ(m.interior_texture[0].pigment.transform.point(Vec3(0, 0, 0)), Vec3(1, 2, 3));
    // An object without one has none.
    auto plain = parse("sphere { 0, 1 pigment { rgb 1 } }");
    EXPECT_TRUE(plain.materials[static_cast<size_t>(plain.objects[0].material)]
                    .interior_texture.empty());
}

TEST(InteriorTexture, CsgChildrenInheritItApartFromTheirTexture) {
    // POV-Ray's Post_Process hands texture and interior_texture down each on its own: the
    // second sphere's own texture still shows the union's interior_texture inside.
    auto s = parse("union { sphere { 0, 1 } sphere { 3*x, 1 texture { " + lit("<0, 0, 1>") +
                   " } } texture { " + lit("<1, 0, 0>") + " } interior_texture { " +
                   lit("<0, 1, 0>") + " } }");
    const auto& csg = std::get<scene::Csg>(s.objects[0].shape);
    ASSERT_EQ(csg.children.size(), 2u);
    EXPECT_EQ(csg.children[0].material, -1);  // inherits the union's material
    const scene::Material& second = s.materials[static_cast<size_t>(csg.children[1].material)];
    EXPECT_EQ(second.texture.pigment.color.rgb, Color(0, 0, 1));
    ASSERT_EQ(second.interior_texture.size(), 1u);
    EXPECT_EQ(second.interior_texture[0].pigment.color.rgb, Color(0, 1, 0));
}

TEST(InteriorTexture, ComesWithAMaterialAndNeedsAnExteriorTexture) {
    auto s = parse("sphere { 0, 1 material { texture { " + lit("1") + " } interior_texture { " +
                   lit("<0, 1, 0>") + " } } }");
    const scene::Material& m = s.materials[static_cast<size_t>(s.objects[0].material)];
    ASSERT_EQ(m.interior_texture.size(), 1u);
    EXPECT_EQ(m.interior_texture[0].pigment.color.rgb, Color(0, 1, 0));
    EXPECT_EQ(error_of("sphere { 0, 1 interior_texture { pigment { rgb 1 } } }"),
              "1:54: interior_texture requires an exterior texture");
}

TEST(InteriorTexture, ShownWhereTheRayMeetsTheSurfaceFromInside) {
    const std::string both = " texture { " + lit("<1, 0, 0>") + " } interior_texture { " +
                             lit("<0, 1, 0>") + " }";
    auto s = parse("sphere { 0, 1" + both + " }");
    EXPECT_EQ(trace(s, Vec3(0, 0, -5), Vec3(0, 0, 1)), Color(1, 0, 0));  // from outside
    EXPECT_EQ(trace(s, Vec3(0, 0, 0), Vec3(0, 0, 1)), Color(0, 1, 0));   // from the centre
    // `inverse` turns the sphere's outward normal inwards: seen from outside, it is inside.
    auto inv = parse("sphere { 0, 1" + both + " inverse }");
    EXPECT_EQ(trace(inv, Vec3(0, 0, -5), Vec3(0, 0, 1)), Color(0, 1, 0));
    // Through the cut of a clipped sphere the far half's inside shows.
    auto cut = parse("sphere { 0, 1" + both + " clipped_by { plane { -z, 0 } } }");
    EXPECT_EQ(trace(cut, Vec3(0, 0, -5), Vec3(0, 0, 1)), Color(0, 1, 0));
}

TEST(InteriorTexture, MeshFacesWithTexturesOfTheirOwnShowItFromInside) {
    // Mesh::Determine_Textures: from inside the mesh's interior_texture wins over the face's.
    auto s = parse("mesh { triangle { <-1, -1, 0>, <1, -1, 0>, <0, 1, 0> texture { " +
                   lit("<0, 0, 1>") + " } } texture { " + lit("<1, 0, 0>") +
                   " } interior_texture { " + lit("<0, 1, 0>") + " } }");
    const Color front = trace(s, Vec3(0, 0, -5), Vec3(0, 0, 1));
    const Color back = trace(s, Vec3(0, 0, 5), Vec3(0, 0, -1));
    const Color own(0, 0, 1), inside(0, 1, 0);
    EXPECT_TRUE((front == own && back == inside) || (front == inside && back == own))
        << "front " << front.r << " " << front.g << " " << front.b << ", back " << back.r << " "
        << back.g << " " << back.b;
}

TEST(InteriorTexture, FiltersShadowRaysLeavingTheObject) {
    // A sphere between a light and the floor, clear outside: the shadow ray enters through
    // the outside's texture and leaves through the inside's, which decides the shadow.
    auto scene_with = [](const std::string& inside) {
        return parse("light_source { <0, 10, 0>, rgb 1 }"
                     "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }"
                     "sphere { <0, 3, 0>, 1 texture { pigment { rgbt 1 } } interior_texture { "
                     "pigment { " + inside + " } } }");
    };
    const Color clear = trace(scene_with("rgbt 1"), Vec3(0, 5, -10), Vec3(0, -5, 10));
    const Color dark = trace(scene_with("rgb 1"), Vec3(0, 5, -10), Vec3(0, -5, 10));
    EXPECT_GT(clear.r, 0.01);
    EXPECT_EQ(dark, Color(0, 0, 0));
}

// Writes a 4 x 1 palette PNG whose pixels use entries 0, 1, 3 and 5 of six.
void write_index_png(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_TRUE(f);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, 4, 1, 8, PNG_COLOR_TYPE_PALETTE, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_color palette[6] = {{0, 0, 0},   {10, 10, 10}, {20, 20, 20},
                            {30, 30, 30}, {40, 40, 40}, {50, 50, 50}};
    png_set_PLTE(png, info, palette, 6);
    png_write_info(png, info);
    png_byte row[4] = {0, 1, 3, 5};
    png_write_row(png, row);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}

class MaterialMapTest : public ::testing::Test {
protected:
    void SetUp() override {
        const char* test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        path_ = (std::filesystem::temp_directory_path() /
                 ("glint_matmap_" + std::string(test) + ".png"))
                    .string();
        write_index_png(path_);
    }
    void TearDown() override { std::remove(path_.c_str()); }
    // Three textures red, green, blue under `items` (once, map_type, ...).
    std::string scene_text(const std::string& items = "") const {
        return "plane { -z, 0 texture { material_map { png \"" + path_ + "\" " + items +
               " texture { " + lit("<1, 0, 0>") + " } texture { " + lit("<0, 1, 0>") +
               " } texture { " + lit("<0, 0, 1>") + " } } } }";
    }
    std::string path_;
};

TEST_F(MaterialMapTest, ParsedAsAnImagePatternOfTextures) {
    auto s = parse(scene_text("map_type 0 once interpolate 0") + " sphere { 0, 1 texture { "
                   "material_map { png \"" + path_ + "\" texture { pigment { rgb 1 } } } "
                   "scale 2 } }");
    const scene::Texture& t = s.materials[static_cast<size_t>(s.objects[0].material)].texture;
    EXPECT_EQ(t.kind, scene::PatternKind::ImageMap);
    EXPECT_TRUE(t.params.image.once);
    ASSERT_EQ(t.entries.size(), 3u);
    EXPECT_EQ(t.entries[2].pigment.color.rgb, Color(0, 0, 1));
    const scene::Texture& scaled =
        s.materials[static_cast<size_t>(s.objects[1].material)].texture;
    EXPECT_EQ(scaled.transform.point(Vec3(1, 1, 1)), Vec3(2, 2, 2));
    EXPECT_NE(error_of("plane { y, 0 texture { material_map { png \"" + path_ + "\" } } }")
                  .find("a material_map needs at least one texture"),
              std::string::npos);
    EXPECT_NE(error_of("plane { y, 0 texture { pigment { rgb 1 } material_map { png \"" + path_ +
                       "\" texture { } } } }"),
              "(no error)");
}

TEST_F(MaterialMapTest, PaletteIndexPicksTheTextureAndWrapsPastTheCount) {
    auto s = parse(scene_text());
    // Planar mapping: x in [0, 1) spans the four pixels, the plane's z = 0 faces -z.
    auto at = [&](double x) { return trace(s, Vec3(x, 0.5, -1), Vec3(0, 0, 1)); };
    EXPECT_EQ(at(0.125), Color(1, 0, 0));  // index 0
    EXPECT_EQ(at(0.375), Color(0, 1, 0));  // index 1
    EXPECT_EQ(at(0.625), Color(0, 0, 1));  // index 3 = the count: the last texture
    EXPECT_EQ(at(0.875), Color(0, 0, 1));  // index 5 wraps to 5 mod 3 = 2
    // The image repeats, so does the choice.
    EXPECT_EQ(at(1.375), Color(0, 1, 0));
    // Used `once`: off the image, the first texture.
    auto once = parse(scene_text("once"));
    EXPECT_EQ(trace(once, Vec3(1.375, 0.5, -1), Vec3(0, 0, 1)), Color(1, 0, 0));
    EXPECT_EQ(trace(once, Vec3(0.375, 0.5, -1), Vec3(0, 0, 1)), Color(0, 1, 0));
}

TEST_F(MaterialMapTest, InterpolationBlendsTheIndicesAndTruncates) {
    // x = 0.26 lies in pixel 1 (index 1), 0.54 of the way from pixel 0's centre to pixel 1's:
    // bilinear gives index 0.54, truncated to 0 (POV-Ray's Interp).
    auto nearest = parse(scene_text());
    auto bilinear = parse(scene_text("interpolate 2"));
    EXPECT_EQ(trace(nearest, Vec3(0.26, 0.5, -1), Vec3(0, 0, 1)), Color(0, 1, 0));
    EXPECT_EQ(trace(bilinear, Vec3(0.26, 0.5, -1), Vec3(0, 0, 1)), Color(1, 0, 0));
    // 0.58 of the way from index 1 to index 3: index 2.16, the third texture.
    EXPECT_EQ(trace(bilinear, Vec3(0.52, 0.5, -1), Vec3(0, 0, 1)), Color(0, 0, 1));
}

}  // namespace
}  // namespace glint
