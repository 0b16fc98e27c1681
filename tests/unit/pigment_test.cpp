// Pigment evaluation against POV-Ray 3.7's definitions: checker parity, gradient wrapping,
// color_map interpolation, the default map, pattern transforms and image_map lookups.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <png.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/error.h"
#include "render/materials/opacity.h"
#include "render/textures/pigment.h"
#include "unit/pov_test_util.h"

namespace glint::render {
namespace {

using scene::ColorFT;
using scene::Pigment;

Pigment plain(Color c) {
    Pigment p;
    p.color = ColorFT(c);
    return p;
}

ColorFT eval(const PigmentEvaluator& e, const Pigment& p, Vec3 at) {
    ColorFT c;
    EXPECT_TRUE(e.evaluate(p, {at, {}, false}, &c));
    return c;
}

TEST(Pigment, PlainColor) {
    PigmentEvaluator e(nullptr);
    Pigment p;
    p.color = ColorFT(Color(0.2, 0.4, 0.6), 0.1, 0.3);
    ColorFT c = eval(e, p, Vec3(5, 6, 7));
    EXPECT_EQ(c, p.color);
}

TEST(Pigment, CheckerParity) {
    PigmentEvaluator e(nullptr);
    Pigment p;
    p.kind = scene::PatternKind::Checker;
    p.entries = {plain(Color(1, 0, 0)), plain(Color(0, 0, 1))};
    EXPECT_EQ(eval(e, p, Vec3(0.5, 0.5, 0.5)).rgb, Color(1, 0, 0));
    EXPECT_EQ(eval(e, p, Vec3(1.5, 0.5, 0.5)).rgb, Color(0, 0, 1));
    EXPECT_EQ(eval(e, p, Vec3(1.5, 1.5, 0.5)).rgb, Color(1, 0, 0));
    EXPECT_EQ(eval(e, p, Vec3(-0.5, 0.5, 0.5)).rgb, Color(0, 0, 1));
    // POV-Ray nudges by EPSILON: a point a hair below an integer counts as on it.
    EXPECT_EQ(eval(e, p, Vec3(1.0 - 1e-12, 0.5, 0.5)).rgb, Color(0, 0, 1));
}

TEST(Pigment, CheckerDefaultsToBlueAndGreen) {
    PigmentEvaluator e(nullptr);
    Pigment p;
    p.kind = scene::PatternKind::Checker;
    EXPECT_EQ(eval(e, p, Vec3(0.5, 0.5, 0.5)).rgb, Color(0, 0, 1));
    EXPECT_EQ(eval(e, p, Vec3(1.5, 0.5, 0.5)).rgb, Color(0, 1, 0));
}

TEST(Pigment, CheckerScaledByTransform) {
    PigmentEvaluator e(nullptr);
    Pigment p;
    p.kind = scene::PatternKind::Checker;
    p.entries = {plain(Color(1, 1, 1)), plain(Color(0, 0, 0))};
    p.transform = Transform::scale(Vec3(2, 2, 2));
    EXPECT_EQ(eval(e, p, Vec3(1.5, 0.5, 0.5)).rgb, Color(1, 1, 1));  // still cell 0
    EXPECT_EQ(eval(e, p, Vec3(2.5, 0.5, 0.5)).rgb, Color(0, 0, 0));
}

TEST(Pigment, GradientDefaultMapIsBlackToWhite) {
    PigmentEvaluator e(nullptr);
    Pigment p;
    p.kind = scene::PatternKind::Gradient;
    p.params.vector = Vec3(1, 0, 0);
    ColorFT c = eval(e, p, Vec3(0.25, 9, 9));
    EXPECT_NEAR(c.rgb.r, 0.25, 1e-12);
    EXPECT_NEAR(c.rgb.g, 0.25, 1e-12);
    // Negative values wrap into [0, 1): -0.25 -> 0.75.
    EXPECT_NEAR(eval(e, p, Vec3(-0.25, 0, 0)).rgb.r, 0.75, 1e-12);
    // Values above 1 wrap: 1.5 -> 0.5.
    EXPECT_NEAR(eval(e, p, Vec3(1.5, 0, 0)).rgb.r, 0.5, 1e-12);
}

TEST(Pigment, ColorMapInterpolatesAllChannels) {
    PigmentEvaluator e(nullptr);
    Pigment p;
    p.kind = scene::PatternKind::Gradient;
    p.params.vector = Vec3(0, 1, 0);
    p.color_map = {{0.2, ColorFT(Color(1, 0, 0), 0.0, 0.0)},
                   {0.6, ColorFT(Color(0, 0, 1), 0.4, 0.8)}};
    // Below the first entry: the first color; above the last: the last.
    EXPECT_EQ(eval(e, p, Vec3(0, 0.1, 0)).rgb, Color(1, 0, 0));
    EXPECT_EQ(eval(e, p, Vec3(0, 0.9, 0)).rgb, Color(0, 0, 1));
    ColorFT mid = eval(e, p, Vec3(0, 0.3, 0));  // a quarter of the way
    EXPECT_NEAR(mid.rgb.r, 0.75, 1e-12);
    EXPECT_NEAR(mid.rgb.b, 0.25, 1e-12);
    EXPECT_NEAR(mid.filter, 0.1, 1e-12);
    EXPECT_NEAR(mid.transmit, 0.2, 1e-12);
}

TEST(Pigment, FrequencyAndPhase) {
    Pigment p;
    p.kind = scene::PatternKind::Gradient;
    p.params.vector = Vec3(1, 0, 0);
    p.params.frequency = 2;
    p.params.phase = 0.1;
    // fmod(0.3 * 2 + 0.1, 1.00001)
    EXPECT_NEAR(PigmentEvaluator(nullptr).pattern_value(p, Vec3(0.3, 0, 0)), 0.7, 1e-12);
    p.params.wave = scene::WaveType::Triangle;
    EXPECT_NEAR(PigmentEvaluator(nullptr).pattern_value(p, Vec3(0.3, 0, 0)), 0.6, 1e-12);
}

// `#declare P = function { pigment { checker red, blue } }` and a pigment
// `function { P(x, y, z).red }`: the pigment is evaluated where the function is called.
TEST(Pigment, PigmentFunctionCalledFromAFunction) {
    std::vector<scene::Function> fns(2);
    fns[0].kind = scene::FunctionKind::Pigment;
    Pigment checker;
    checker.kind = scene::PatternKind::Checker;
    checker.entries = {plain(Color(1, 0, 0)), plain(Color(0, 0, 1))};
    fns[0].pigment = {checker};
    scene::Function& f = fns[1];
    f.params = {"x", "y", "z"};
    f.slots = 3;
    for (int k = 0; k < 3; ++k) {
        scene::FnNode n;
        n.op = scene::FnOp::Param;
        n.index = k;
        f.nodes.push_back(n);
    }
    scene::FnNode call;
    call.op = scene::FnOp::Call;
    call.index = 0;
    call.member = 0;  // .red
    call.first = 0;
    call.count = 3;
    f.nodes.push_back(call);
    f.operands = {0, 1, 2};
    f.root = 3;
    Pigment p;
    p.kind = scene::PatternKind::Function;
    p.params.function = 1;
    p.color_map = {{0.0, ColorFT(Color(0, 0, 0))}, {1.0, ColorFT(Color(1, 1, 1))}};
    PatternContext ctx;
    ctx.functions = &fns;
    PigmentEvaluator e(nullptr, ctx);
    EXPECT_EQ(eval(e, p, Vec3(0.5, 0.5, 0.5)).rgb, Color(1, 1, 1));  // red square: red 1
    EXPECT_EQ(eval(e, p, Vec3(1.5, 0.5, 0.5)).rgb, Color(0, 0, 0));  // blue square: red 0
}

// pigment { pigment_pattern { checker rgb 1, rgb <0, 0, 1> scale 2 } color_map { ... } }:
// the inner pigment's grey (0.297 r + 0.589 g + 0.114 b), the inner transform relative to
// the pattern's space.
TEST(Pigment, PigmentPatternIsTheInnerPigmentsGrey) {
    auto inner = std::make_shared<Pigment>();
    inner->kind = scene::PatternKind::Checker;
    inner->entries = {plain(Color(1, 1, 1)), plain(Color(0, 0, 1))};
    inner->transform = Transform::scale(Vec3(2, 2, 2));
    Pigment p;
    p.kind = scene::PatternKind::PigmentPattern;
    p.params.pigment = inner;
    p.params.frequency = 0;  // the raw value, no fmod
    p.color_map = {{0.0, ColorFT(Color(0, 0, 0))}, {1.0, ColorFT(Color(1, 0, 0))}};
    p.transform = Transform::translate(Vec3(10, 0, 0));
    PigmentEvaluator e(nullptr);
    EXPECT_NEAR(eval(e, p, Vec3(11, 1, 1)).rgb.r, 1.0, 1e-12);    // white square
    EXPECT_NEAR(eval(e, p, Vec3(13, 1, 1)).rgb.r, 0.114, 1e-12);  // blue square
    EXPECT_EQ(eval(e, p, Vec3(13, 1, 1)).rgb.g, 0.0);
}

// aoi: acos(n . d) / pi with n the normal facing the ray: 1 head on, 0.75 at 45 degrees,
// 0.5 at grazing incidence; 0 without a surface or a ray.
TEST(Pigment, AoiReadsTheAngleOfIncidence) {
    Pigment p;
    p.kind = scene::PatternKind::Aoi;
    p.params.frequency = 0;
    p.color_map = {{0.0, ColorFT(Color(0, 0, 0))}, {1.0, ColorFT(Color(1, 1, 1))}};
    PigmentEvaluator e(nullptr);
    const Vec3 n(0, 1, 0);
    auto at = [&](Vec3 d) {
        ColorFT c;
        EXPECT_TRUE(e.evaluate(p, {Vec3(0, 0, 0), {}, false, &n, &d}, &c));
        return c.rgb.r;
    };
    EXPECT_NEAR(at(Vec3(0, -2, 0)), 1.0, 1e-12);
    EXPECT_NEAR(at(Vec3(1, -1, 0)), 0.75, 1e-12);
    EXPECT_NEAR(at(Vec3(1, 0, 0)), 0.5, 1e-12);
    ColorFT none;
    EXPECT_TRUE(e.evaluate(p, {Vec3(0, 0, 0), {}, false, &n}, &none));
    EXPECT_EQ(none.rgb.r, 0.0);
}

// slope { y }: 0.5 + asin(dot(n, y)) / pi, so 1 (just below) facing up, 0.5 on a wall, 0
// facing down; with altitude the height mixes in by the vectors' length ratio.
TEST(Pigment, SlopeReadsTheSurfaceNormal) {
    Pigment p;
    p.kind = scene::PatternKind::Slope;
    p.params.slope.vector = Vec3(0, 1, 0);
    p.params.slope.base = 2;  // +y, as the parser marks it
    p.params.frequency = 0;
    p.color_map = {{0.0, ColorFT(Color(0, 0, 0))}, {1.0, ColorFT(Color(1, 1, 1))}};
    PigmentEvaluator e(nullptr);
    auto at = [&](Vec3 n, Vec3 q) {
        ColorFT c;
        EXPECT_TRUE(e.evaluate(p, {q, {}, false, &n}, &c));
        return c.rgb.r;
    };
    EXPECT_NEAR(at(Vec3(0, 1, 0), Vec3(0, 0, 0)), 1.0, 1e-9);
    EXPECT_NEAR(at(Vec3(1, 0, 0), Vec3(0, 0, 0)), 0.5, 1e-12);
    EXPECT_NEAR(at(normalize(Vec3(1, 1, 0)), Vec3(0, 0, 0)), 0.75, 1e-12);
    EXPECT_NEAR(at(Vec3(0, -1, 0), Vec3(0, 0, 0)), 0.0, 1e-12);
    // No surface (media, functions): 0.
    ColorFT none;
    EXPECT_TRUE(e.evaluate(p, {Vec3(0, 0, 0), {}, false}, &none));
    EXPECT_EQ(none.rgb.r, 0.0);
    // altitude <0, 1, 0>, 0, 10 with equal weights: half the slope plus half of y / 10.
    p.params.slope.altitude = Vec3(0, 1, 0);
    p.params.slope.altitude_base = 2;
    p.params.slope.altitude_span = 10;
    p.params.slope.weight = p.params.slope.altitude_weight = 0.5;
    EXPECT_NEAR(at(Vec3(1, 0, 0), Vec3(0, 4, 0)), 0.25 + 0.2, 1e-12);
}

TEST(Pigment, NestedEntriesLiveInTheParentsPatternSpace) {
    // POV-Ray evaluates entries at the parent's warped pattern-space point, so an entry's
    // transform is relative: the outer checker is scaled by 10 and the inner one by 0.5 of
    // that (5 in world space).
    PigmentEvaluator e(nullptr);
    Pigment inner;
    inner.kind = scene::PatternKind::Checker;
    inner.entries = {plain(Color(1, 1, 1)), plain(Color(0, 0, 0))};
    inner.transform = Transform::scale(Vec3(0.5, 0.5, 0.5));
    Pigment outer;
    outer.kind = scene::PatternKind::Checker;
    outer.entries = {inner, plain(Color(1, 0, 0))};
    outer.transform = Transform::scale(Vec3(10, 10, 10));
    EXPECT_EQ(eval(e, outer, Vec3(2.5, 2.5, 2.5)).rgb, Color(1, 1, 1));
    EXPECT_EQ(eval(e, outer, Vec3(7.5, 2.5, 2.5)).rgb, Color(0, 0, 0));
    EXPECT_EQ(eval(e, outer, Vec3(15.5, 2.5, 2.5)).rgb, Color(1, 0, 0));
}

TEST(Pigment, UvMappingUsesSurfaceCoordinates) {
    PigmentEvaluator e(nullptr);
    Pigment p;
    p.kind = scene::PatternKind::Gradient;
    p.params.vector = Vec3(1, 0, 0);
    p.uv_mapping = true;
    ColorFT c;
    ASSERT_TRUE(e.evaluate(p, {Vec3(0.9, 0, 0), Vec2(0.25, 0.5), true}, &c));
    EXPECT_NEAR(c.rgb.r, 0.25, 1e-12);
    // A surface without uv of its own: the world point's x and y (ObjectBase::UVCoord).
    ASSERT_TRUE(e.evaluate(p, {Vec3(0.375, 0.5, 0.9), Vec2(), false}, &c));
    EXPECT_NEAR(c.rgb.r, 0.375, 1e-12);
}

class ImageMapTest : public ::testing::Test {
protected:
    void SetUp() override {
        path_ = (std::filesystem::temp_directory_path() /
                 ("glint_pigment_test_" + std::to_string(::getpid()) + ".png"))
                    .string();
        // 2 x 2 RGBA: top row red, green; bottom row blue, white half transparent.
        const unsigned char px[16] = {255, 0, 0, 255, 0, 255, 0, 255,
                                      0, 0, 255, 255, 255, 255, 255, 128};
        auto out = OIIO::ImageOutput::create(path_);
        ASSERT_TRUE(out);
        OIIO::ImageSpec spec(2, 2, 4, OIIO::TypeDesc::UINT8);
        ASSERT_TRUE(out->open(path_, spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px));
        out->close();
    }
    void TearDown() override { std::remove(path_.c_str()); }

    Pigment image_pigment() const {
        Pigment p;
        p.kind = scene::PatternKind::ImageMap;
        p.params.image.file = path_;
        p.params.image.resolved_path = path_;
        return p;
    }

    std::string path_;
};

TEST_F(ImageMapTest, PlanarMapPutsTheImageOnTheUnitSquare) {
    Pigment p = image_pigment();
    scene::Scene s;
    s.materials.resize(1);
    s.materials[0].texture.pigment = p;
    TextureCache cache(image_gamma(s));  // 3.7 scene: sRGB decoded
    cache.preload(s);
    ASSERT_EQ(cache.size(), 1u);
    PigmentEvaluator e(&cache);
    // Image y runs up: the top row is at y in [0.5, 1).
    EXPECT_EQ(eval(e, p, Vec3(0.25, 0.75, 0)).rgb, Color(1, 0, 0));
    EXPECT_EQ(eval(e, p, Vec3(0.75, 0.75, 0)).rgb, Color(0, 1, 0));
    EXPECT_EQ(eval(e, p, Vec3(0.25, 0.25, 0)).rgb, Color(0, 0, 1));
    ColorFT w = eval(e, p, Vec3(0.75, 0.25, 0));
    EXPECT_EQ(w.rgb, Color(1, 1, 1));
    EXPECT_NEAR(w.transmit, 1.0 - 128.0 / 255.0, 1e-6);
    // Repeats without `once`.
    EXPECT_EQ(eval(e, p, Vec3(1.25, -0.25, 0)).rgb, Color(1, 0, 0));  // = (0.25, 0.75)
}

TEST_F(ImageMapTest, ImagePatternIsTheGreyOrTheAlphaReadAsData) {
    // image_pattern { "file" } as a pigment pattern: the texel's grey (0.297 r + 0.589 g +
    // 0.114 b) picks the colour map's value; the file's values as stored (no sRGB decoding),
    // and under use_alpha the transmit.
    Pigment p;
    p.kind = scene::PatternKind::ImagePattern;
    p.params.image.file = path_;
    p.params.image.resolved_path = path_;
    p.params.image.data = true;
    p.params.frequency = 0;
    scene::Scene s;
    s.materials.resize(1);
    s.materials[0].texture.pigment = p;
    TextureCache cache(image_gamma(s));  // a 3.7 scene: an image_map would be sRGB decoded
    cache.preload(s);
    ASSERT_EQ(cache.size(), 1u);
    PigmentEvaluator e(&cache);
    // POV-Ray's default map runs black to white: the value shows as the grey.
    EXPECT_NEAR(eval(e, p, Vec3(0.25, 0.75, 0)).rgb.r, 0.297, 1e-6);  // red texel
    EXPECT_NEAR(eval(e, p, Vec3(0.75, 0.75, 0)).rgb.r, 0.589, 1e-6);  // green
    EXPECT_NEAR(eval(e, p, Vec3(0.75, 0.25, 0)).rgb.r, 1.0, 1e-6);    // white
    Pigment a = p;
    a.params.image.use_alpha = true;
    EXPECT_NEAR(eval(e, a, Vec3(0.75, 0.25, 0)).rgb.r, 1.0 - 128.0 / 255.0, 1e-6);
    EXPECT_NEAR(eval(e, a, Vec3(0.25, 0.75, 0)).rgb.r, 0.0, 1e-6);  // opaque
    // The same file as an image_map is another (decoded) image in the cache.
    s.materials[0].texture.pigment = image_pigment();
    cache.preload(s);
    EXPECT_EQ(cache.size(), 2u);
}

TEST_F(ImageMapTest, ImagePatternParsesAsAContinuousPatternOfData) {
    auto s = pov::testing::parse("plane { y, 0 pigment { image_pattern { png \"" + path_ +
                                 "\" use_alpha map_type 1 once } "
                                 "color_map { [0 rgb 0] [1 rgb 1] } } "
                                 "normal { image_pattern { \"" + path_ + "\" } 0.5 } }");
    const scene::Texture& t = s.materials.back().texture;
    EXPECT_EQ(t.pigment.kind, scene::PatternKind::ImagePattern);
    EXPECT_TRUE(t.pigment.params.image.data);
    EXPECT_TRUE(t.pigment.params.image.use_alpha);
    EXPECT_TRUE(t.pigment.params.image.once);
    EXPECT_EQ(t.pigment.params.image.map_type, 1);
    EXPECT_EQ(t.pigment.params.frequency, 0);  // values are not reshaped
    EXPECT_EQ(t.pigment.color_map.size(), 2u);
    EXPECT_EQ(t.normal.kind, scene::PatternKind::ImagePattern);
    EXPECT_FALSE(t.normal.params.image.use_alpha);
    EXPECT_NE(pov::testing::error_of("plane { y, 0 pigment { image_pattern { \"" + path_ +
                                     "\" bump_size 2 } } }")
                  .find("expected an image_map item"),
              std::string::npos);
}

TEST_F(ImageMapTest, OnceLeavesTheOutsideClear) {
    Pigment p = image_pigment();
    p.params.image.once = true;
    scene::Scene s;
    s.materials.resize(1);
    s.materials[0].texture.pigment = p;
    TextureCache cache(image_gamma(s));
    cache.preload(s);
    PigmentEvaluator e(&cache);
    ColorFT c;
    EXPECT_FALSE(e.evaluate(p, {Vec3(1.25, 0.5, 0), {}, false}, &c));
    EXPECT_EQ(c.transmit, 1.0);
}

// What the shadow walk and the scene's opaque-object query (materials/opacity.h) take as able
// to let light through: an image with alpha, or any image with once, filter all or transmit
// all; an opaque RGB image is opaque once its file is known, and unknown files may be clear.
TEST_F(ImageMapTest, OpacityFollowsAlphaOnceAndFilter) {
    const std::string rgba = path_;
    const std::string rgb = path_ + ".rgb.png";
    const unsigned char px[12] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    auto out = OIIO::ImageOutput::create(rgb);
    OIIO::ImageSpec spec(2, 2, 3, OIIO::TypeDesc::UINT8);
    ASSERT_TRUE(out->open(rgb, spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px));
    out->close();
    auto pig = [&](const std::string& file) {
        Pigment p = image_pigment();
        p.params.image.file = p.params.image.resolved_path = file;
        return p;
    };
    scene::Scene s;
    s.materials.resize(2);
    s.materials[0].texture.pigment = pig(rgba);
    s.materials[1].texture.pigment = pig(rgb);
    TextureCache cache(image_gamma(s));
    cache.preload(s);
    EXPECT_TRUE(render::pigment_can_be_transparent(pig(rgba), &cache));
    EXPECT_FALSE(render::pigment_can_be_transparent(pig(rgb), &cache));
    EXPECT_TRUE(render::pigment_can_be_transparent(pig(rgb), nullptr));
    Pigment once = pig(rgb), filtered = pig(rgb), transmitted = pig(rgb);
    once.params.image.once = true;
    filtered.params.image.filter_all = 0.2;
    transmitted.params.image.transmit_all = 0.2;
    EXPECT_TRUE(render::pigment_can_be_transparent(once, &cache));
    EXPECT_TRUE(render::pigment_can_be_transparent(filtered, &cache));
    EXPECT_TRUE(render::pigment_can_be_transparent(transmitted, &cache));
    std::remove(rgb.c_str());
}

// Writes a 2 x 1 palette PNG at `path`: pixel 0 uses entry 2, pixel 1 entry 0; the palette
// has three entries, the first and last of the same colour.
void write_palette_png(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_TRUE(f);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, 2, 1, 8, PNG_COLOR_TYPE_PALETTE, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_color palette[3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}};
    png_set_PLTE(png, info, palette, 3);
    png_write_info(png, info);
    png_byte row[2] = {2, 0};
    png_write_row(png, row);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}

// filter N, V and transmit N, V set one palette entry, and on a palette image filter all /
// transmit all set every entry, in the order written (POV-Ray's Parse_Image_Map).
TEST_F(ImageMapTest, PaletteEntriesTakeFilterAndTransmitInOrder) {
    write_palette_png(path_);
    Pigment p = image_pigment();
    using Edit = scene::ImageMap::PaletteEdit;
    p.params.image.palette_edits = {Edit{2, false, 0.7, {}}, Edit{-1, true, 0.3, {}},
                                    Edit{0, true, 0.9, {}}, Edit{-1, false, 0.25, {}},
                                    Edit{2, false, 0.6, {}}};
    p.params.image.filter_all = 0.3;
    p.params.image.transmit_all = 0.25;
    scene::Scene s;
    s.materials.resize(1);
    s.materials[0].texture.pigment = p;
    TextureCache cache(image_gamma(s));
    cache.preload(s);
    PigmentEvaluator e(&cache);
    ColorFT left = eval(e, p, Vec3(0.25, 0.5, 0)), right = eval(e, p, Vec3(0.75, 0.5, 0));
    EXPECT_EQ(left.rgb, Color(0, 0, 1));  // entry 2
    EXPECT_DOUBLE_EQ(left.filter, 0.3);
    EXPECT_DOUBLE_EQ(left.transmit, 0.6);
    EXPECT_EQ(right.rgb, Color(1, 0, 0));  // entry 0
    EXPECT_DOUBLE_EQ(right.filter, 0.9);
    EXPECT_DOUBLE_EQ(right.transmit, 0.25);
    EXPECT_TRUE(render::pigment_can_be_transparent(p, &cache));

    // Entry 3 does not exist; an RGB image has no entries at all.
    Pigment past = p;
    past.params.image.palette_edits = {Edit{3, true, 0.5, {}}};
    s.materials[0].texture.pigment = past;
    TextureCache cache2(image_gamma(s));
    EXPECT_THROW(cache2.preload(s), Error);
}

// The palette index beside the colour, as a use_index bump_map reads it: the texel's entry
// without interpolation, the corners' entries blended and truncated with it (Interp); -1 on
// an image without a palette.
TEST_F(ImageMapTest, SamplesReportPaletteIndices) {
    write_palette_png(path_);
    Pigment p = image_pigment();
    scene::Scene s;
    s.materials.resize(1);
    s.materials[0].texture.pigment = p;
    TextureCache cache(image_gamma(s));
    cache.preload(s);
    const render::ImageTexture* tex = cache.find(p.params.image);
    ASSERT_TRUE(tex);
    int index = 99;
    render::image_map_sample(p.params.image, *tex, 0.5, 0.5, &index);
    EXPECT_EQ(index, 2);
    render::image_map_sample(p.params.image, *tex, 1.5, 0.5, &index);
    EXPECT_EQ(index, 0);
    scene::ImageMap bilinear = p.params.image;
    bilinear.interpolate = 2;
    // Half way between the texel centres: (2 + 0) / 2.
    render::image_map_sample(bilinear, *tex, 1.0, 0.5, &index);
    EXPECT_EQ(index, 1);
    // A quarter of the way from entry 2 to entry 0: 1.5, truncated.
    render::image_map_sample(bilinear, *tex, 0.75, 0.5, &index);
    EXPECT_EQ(index, 1);
    render::image_map_sample(bilinear, *tex, 0.6, 0.5, &index);
    EXPECT_EQ(index, 1);  // 1.8
    render::image_map_sample(bilinear, *tex, 0.51, 0.5, &index);
    EXPECT_EQ(index, 1);  // 1.98
}

TEST_F(ImageMapTest, RgbSamplesHaveNoPaletteIndex) {
    Pigment p = image_pigment();
    scene::Scene s;
    s.materials.resize(1);
    s.materials[0].texture.pigment = p;
    TextureCache cache(image_gamma(s));
    cache.preload(s);
    int index = 99;
    render::image_map_sample(p.params.image, *cache.find(p.params.image), 0.5, 0.5, &index);
    EXPECT_EQ(index, -1);
}

TEST_F(ImageMapTest, PaletteEditsNeedAPaletteImage) {
    Pigment p = image_pigment();  // the fixture's RGBA image
    p.params.image.palette_edits = {scene::ImageMap::PaletteEdit{0, false, 0.5, {}}};
    scene::Scene s;
    s.materials.resize(1);
    s.materials[0].texture.pigment = p;
    TextureCache cache(image_gamma(s));
    EXPECT_THROW(cache.preload(s), Error);
}

TEST_F(ImageMapTest, GammaDecodingFollowsTheSceneVersion) {
    // A mid-grey texel through the bilinear path would mix; use a one-texel lookup instead.
    const unsigned char grey[4] = {128, 128, 128, 255};
    auto out = OIIO::ImageOutput::create(path_);
    OIIO::ImageSpec spec(1, 1, 4, OIIO::TypeDesc::UINT8);
    ASSERT_TRUE(out->open(path_, spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, grey));
    out->close();
    Pigment p = image_pigment();
    scene::Scene s;
    s.materials.resize(1);
    s.materials[0].texture.pigment = p;
    {
        TextureCache cache(image_gamma(s));  // 3.7, no assumed_gamma: linear working space
        cache.preload(s);
        PigmentEvaluator e(&cache);
        double v = 128.0 / 255.0;
        EXPECT_NEAR(eval(e, p, Vec3(0.5, 0.5, 0)).rgb.r, std::pow((v + 0.055) / 1.055, 2.4), 1e-6);
    }
    s.version = 3.6;  // no assumed_gamma: gamma handling off, values used as stored
    TextureCache legacy(image_gamma(s));
    legacy.preload(s);
    PigmentEvaluator e(&legacy);
    EXPECT_NEAR(eval(e, p, Vec3(0.5, 0.5, 0)).rgb.r, 128.0 / 255.0, 1e-6);
}

TEST_F(ImageMapTest, BilinearInterpolationBlendsNeighbours) {
    Pigment p = image_pigment();
    p.params.image.interpolate = 2;
    p.params.image.once = true;
    scene::Scene s;
    s.version = 3.6;
    s.materials.resize(1);
    s.materials[0].texture.pigment = p;
    TextureCache cache(image_gamma(s));
    cache.preload(s);
    PigmentEvaluator e(&cache);
    // Exactly between the centres of the top texels (red and green).
    ColorFT c = eval(e, p, Vec3(0.5, 0.75, 0));
    EXPECT_NEAR(c.rgb.r, 0.5, 1e-6);
    EXPECT_NEAR(c.rgb.g, 0.5, 1e-6);
    EXPECT_NEAR(c.rgb.b, 0.0, 1e-6);
}

}  // namespace
}  // namespace glint::render
