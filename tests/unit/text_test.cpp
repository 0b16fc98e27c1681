// text objects: POV-Ray's glyph layout (kerning, offset, first glyph at the origin), the
// extruded-outline intersection (caps, walls, holes of the outline) and the parser's text
// statement with its errors. Needs the fonts of Debian's povray-includes.
#include <gtest/gtest.h>

#include <filesystem>

#include "render/shapes/text/font.h"
#include "render/shapes/text/text.h"
#include "unit/pov_test_util.h"

namespace glint {
namespace {

const std::string kFonts = "/usr/share/povray-3.7/include/";

bool have_fonts() { return std::filesystem::exists(kFonts + "timrom.ttf"); }

TEST(TextLayout, FirstGlyphStartsAtOriginAndKerningPullsPairsTogether) {
    if (!have_fonts()) GTEST_SKIP() << "povray-includes not installed";
    using render::layout_text;
    auto av = layout_text(kFonts + "timrom.ttf", "AV", Vec3(0, 0, 0));
    auto ax = layout_text(kFonts + "timrom.ttf", "Ax", Vec3(0, 0, 0));
    ASSERT_EQ(av.glyphs.size(), 2u);
    // timrom's A: xMin 6 font units of 1000, so it is moved left by 0.006.
    EXPECT_DOUBLE_EQ(av.glyphs[0].offset.x, -0.006);
    EXPECT_NEAR(av.glyphs[0].lo.x + av.glyphs[0].offset.x, 0.0, 1e-12);
    // V after A sits closer than the advance alone would put it (a negative kern pair).
    double v_left = av.glyphs[1].offset.x + av.glyphs[1].lo.x;
    double x_left = ax.glyphs[1].offset.x + ax.glyphs[1].lo.x;
    EXPECT_LT(v_left, 0.75);
    EXPECT_GT(x_left, 0.7);
    // The offset vector is added after each character.
    auto spaced = layout_text(kFonts + "timrom.ttf", "AV", Vec3(0.5, 0.25, 0));
    EXPECT_NEAR(spaced.glyphs[1].offset.x - av.glyphs[1].offset.x, 0.5, 1e-12);
    EXPECT_NEAR(spaced.glyphs[1].offset.y - av.glyphs[1].offset.y, 0.25, 1e-12);
}

TEST(TextLayout, UnreadableFontIsAMissingFileError) {
    try {
        render::layout_text("/nonexistent/font.ttf", "A", Vec3(0, 0, 0));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::MissingFile);
    }
}

TEST(TextPrimitive, CapsWallsAndTheHoleOfAnO) {
    if (!have_fonts()) GTEST_SKIP() << "povray-includes not installed";
    scene::Text t;
    t.font = kFonts + "timrom.ttf";
    t.text = "o";
    t.thickness = 0.5;
    const char* why = nullptr;
    auto prim = render::make_text(t, FileLoc{}, &why);
    ASSERT_TRUE(prim) << why;
    Bounds3 b = prim->bounds();
    double cx = 0.5 * (b.lo.x + b.hi.x), cy = 0.5 * (b.lo.y + b.hi.y);
    // Through the ring of the o (left stroke): front cap at z = 0, back cap at z = 0.5.
    double ring_x = b.lo.x + 0.03;
    render::Ray r{Vec3(ring_x, cy, -2), Vec3(0, 0, 1)};
    render::LocalHit h;
    ASSERT_TRUE(prim->intersect(r, kInfinity, &h));
    EXPECT_NEAR(h.t, 2.0, 1e-9);
    EXPECT_NEAR(h.ng.z, -1.0, 1e-12);
    render::HitList all;
    prim->intersect_all(r, kInfinity, &all);
    EXPECT_EQ(all.size(), 2u);
    EXPECT_TRUE(prim->inside(Vec3(ring_x, cy, 0.25)));
    EXPECT_FALSE(prim->inside(Vec3(ring_x, cy, 0.6)));
    // Through the hole in the middle: nothing.
    render::Ray hole{Vec3(cx, cy, -2), Vec3(0, 0, 1)};
    EXPECT_FALSE(prim->intersect(hole, kInfinity, &h));
    EXPECT_FALSE(prim->inside(Vec3(cx, cy, 0.25)));
    // Sideways at mid-depth: the outer wall of the o, its normal pointing out of the solid;
    // four walls in all (outer, inner, inner, outer).
    render::Ray side{Vec3(b.lo.x - 1, cy, 0.25), Vec3(1, 0, 0)};
    ASSERT_TRUE(prim->intersect(side, kInfinity, &h));
    EXPECT_NEAR(h.p.x, b.lo.x, 2e-3);
    EXPECT_LT(h.ng.x, -0.9);
    all.clear();
    prim->intersect_all(side, kInfinity, &all);
    EXPECT_EQ(all.size(), 4u);
}

TEST(TextParser, TextStatementAndItsErrors) {
    if (!have_fonts()) GTEST_SKIP() << "povray-includes not installed";
    pov::ParseOptions opts;
    opts.include_dirs.push_back(kFonts);
    auto s = pov::testing::parse(
        "text { ttf \"timrom.ttf\" concat(\"a\", \"b\") 0.25, <0.1, 0, 0> }", opts);
    ASSERT_EQ(s.objects.size(), 1u);
    const auto* t = std::get_if<scene::Text>(&s.objects[0].shape);
    ASSERT_TRUE(t);
    EXPECT_EQ(t->file, "timrom.ttf");
    EXPECT_EQ(t->text, "ab");
    EXPECT_EQ(t->thickness, 0.25);
    EXPECT_EQ(t->offset, Vec3(0.1, 0, 0));
    // POV-Ray's anti-crack rotation of 0.001 degrees about each axis.
    EXPECT_FALSE(s.objects[0].transform.is_identity());
    EXPECT_EQ(pov::testing::error_of("text { ttf \"nofont.ttf\" \"x\" 1, 0 }", opts),
              "1:12: cannot find the file 'nofont.ttf'");
    EXPECT_EQ(pov::testing::error_of("text { \"timrom.ttf\" \"x\" 1, 0 }", opts),
              "1:8: expected 'ttf' in text (ttf \"font.ttf\" or internal N, \"string\" thickness, "
              "offset), "
              "got the string \"timrom.ttf\"");
}

TEST(TextParser, BuiltInFontsAreTheFontsPovRayShips) {
    if (!have_fonts()) GTEST_SKIP() << "povray-includes not installed";
    pov::ParseOptions opts;
    opts.include_dirs.push_back(kFonts);
    // POV-Ray 3.7 compiles in copies of its four fonts: 1 timrom, 2 cyrvetic, 3 crystal, and
    // povlogo for any other number (fileinputoutput.cpp).
    const char* expected[] = {"povlogo.ttf", "timrom.ttf", "cyrvetic.ttf", "crystal.ttf",
                              "povlogo.ttf", "povlogo.ttf"};
    const char* ids[] = {"0", "1", "2", "3", "7", "-1"};
    for (int i = 0; i < 6; ++i) {
        auto s = pov::testing::parse(std::string("text { internal ") + ids[i] + " \"Ab\" 0.5, 0 }",
                                     opts);
        ASSERT_EQ(s.objects.size(), 1u) << ids[i];
        const auto* t = std::get_if<scene::Text>(&s.objects[0].shape);
        ASSERT_TRUE(t) << ids[i];
        EXPECT_EQ(t->file, expected[i]) << ids[i];
        EXPECT_EQ(std::filesystem::path(t->font).filename(), expected[i]) << ids[i];
        EXPECT_EQ(t->text, "Ab");
        EXPECT_EQ(t->thickness, 0.5);
    }
}

}  // namespace
}  // namespace glint
