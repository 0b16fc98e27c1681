// POV-Ray patterns, warps, maps, block entries, normals and layered/patterned textures to IR
// (formats/pov/patterns.cpp, pattern_grammar.cpp), and the exact errors for their misuse.
#include <gtest/gtest.h>

#include "tests/unit/pov_test_util.h"

namespace glint::pov {
namespace {

using scene::PatternKind;
using scene::WarpKind;
using testing::error_of;
using testing::parse;

const scene::Texture& texture_of(const scene::Scene& s, size_t object = 0) {
    return s.materials[s.objects[object].material].texture;
}

TEST(PovPatterns, KeywordsAndTheirArguments) {
    auto s = parse(
        "sphere { 0, 1 pigment { agate agate_turb 0.3 } }\n"
        "sphere { 0, 1 pigment { spiral1 5 } }\n"
        "sphere { 0, 1 pigment { julia <0.3, 0.2>, 40 exponent 3 exterior 2, 0.5"
        " interior 1, 2 } }\n"
        "sphere { 0, 1 pigment { crackle metric 1 offset 0.2 solid form <1, 0, 0> } }\n"
        "sphere { 0, 1 pigment { brick brick_size <1, 2, 3> mortar 0.1 } }\n"
        "sphere { 0, 1 normal { facets coords 0.5 size 0.2 metric 3 } }\n"
        "sphere { 0, 1 pigment { quilted control0 0.2 control1 0.8 } }\n"
        "sphere { 0, 1 pigment { marble noise_generator 1 } }\n");
    const auto& agate = texture_of(s, 0).pigment;
    EXPECT_EQ(agate.kind, PatternKind::Agate);
    EXPECT_EQ(agate.params.agate_turb, 0.3);
    // Agate reads octaves/omega/lambda from a classic turbulence warp it always has.
    ASSERT_EQ(agate.params.warps.size(), 1u);
    EXPECT_EQ(agate.params.warps[0].kind, WarpKind::ClassicTurbulence);
    const auto& spiral = texture_of(s, 1).pigment;
    EXPECT_EQ(spiral.params.arms, 5);
    EXPECT_EQ(spiral.params.wave, scene::WaveType::Triangle);
    const auto& julia = texture_of(s, 2).pigment.params;
    EXPECT_EQ(julia.julia_param, Vec2(0.3, 0.2));
    EXPECT_EQ(julia.iterations, 40);
    EXPECT_EQ(julia.fractal_exponent, 3);
    EXPECT_EQ(julia.exterior_type, 2);
    EXPECT_EQ(julia.exterior_factor, 0.5);
    EXPECT_EQ(julia.interior_type, 1);
    EXPECT_EQ(julia.interior_factor, 2);
    const auto& crackle = texture_of(s, 3).pigment.params;
    EXPECT_EQ(crackle.crackle_metric, 1);
    EXPECT_EQ(crackle.crackle_offset, 0.2);
    EXPECT_TRUE(crackle.crackle_solid);
    EXPECT_EQ(crackle.crackle_form, Vec3(1, 0, 0));
    const auto& brick = texture_of(s, 4).pigment;
    EXPECT_EQ(brick.params.brick_size, Vec3(1, 2, 3));
    EXPECT_EQ(brick.params.mortar, 0.1);
    ASSERT_EQ(brick.entries.size(), 2u);  // POV-Ray's default brick colors
    EXPECT_EQ(brick.entries[0].color.rgb, Color(0.5, 0.5, 0.5));
    EXPECT_EQ(brick.entries[1].color.rgb, Color(0.6, 0.15, 0.15));
    const auto& facets = texture_of(s, 5).normal;
    EXPECT_EQ(facets.kind, PatternKind::Facets);
    EXPECT_EQ(facets.params.facets_coords, 0.5);
    EXPECT_EQ(facets.params.facets_size, 0.2);
    EXPECT_EQ(facets.params.facets_metric, 3);
    const auto& quilted = texture_of(s, 6).pigment.params;
    EXPECT_EQ(quilted.control0, 0.2);
    EXPECT_EQ(quilted.control1, 0.8);
    EXPECT_EQ(quilted.frequency, 0);
    EXPECT_EQ(texture_of(s, 7).pigment.params.noise_generator, 1);
}

TEST(PovPatterns, WarpOrderFollowsPovRay) {
    // Transforms written after a warp stay the pattern's own transform; those before it move
    // behind it; turbulence in the pattern appends a classic turbulence warp at the end.
    auto s = parse(
        "sphere { 0, 1 pigment { bozo scale 2 turbulence 0.5 octaves 3 warp { repeat x*2 "
        "offset y flip z } translate x } }");
    const auto& p = texture_of(s).pigment;
    EXPECT_EQ(p.transform.point(Vec3(0, 0, 0)), Vec3(1, 0, 0));
    ASSERT_EQ(p.params.warps.size(), 3u);
    EXPECT_EQ(p.params.warps[0].kind, WarpKind::Repeat);
    EXPECT_EQ(p.params.warps[0].direction, Vec3(2, 0, 0));
    EXPECT_EQ(p.params.warps[0].offset, Vec3(0, 1, 0));
    EXPECT_EQ(p.params.warps[0].flip, Vec3(0, 0, 1));
    EXPECT_EQ(p.params.warps[1].kind, WarpKind::Transform);
    EXPECT_EQ(p.params.warps[1].transform.point(Vec3(1, 1, 1)), Vec3(2, 2, 2));
    EXPECT_EQ(p.params.warps[2].kind, WarpKind::ClassicTurbulence);
    EXPECT_EQ(p.params.warps[2].turbulence.amount, Vec3(0.5, 0.5, 0.5));
    EXPECT_EQ(p.params.warps[2].turbulence.octaves, 3);
}

TEST(PovPatterns, EveryWarpKind) {
    auto s = parse(
        "sphere { 0, 1 pigment { bozo warp { black_hole <1, 0, 0>, 0.5 strength 2 falloff 3 "
        "inverse } warp { cylindrical orientation y dist_exp 1 } warp { spherical } "
        "warp { toroidal major_radius 2 } warp { planar z, 0.5 } warp { cubic } "
        "warp { turbulence 0.2 octaves 2 omega 0.4 lambda 3 } } }");
    const auto& w = texture_of(s).pigment.params.warps;
    ASSERT_EQ(w.size(), 7u);  // written last, applied first
    EXPECT_EQ(w[0].kind, WarpKind::Turbulence);
    EXPECT_EQ(w[0].turbulence.lambda, 3);
    EXPECT_EQ(w[1].kind, WarpKind::Cubic);
    EXPECT_EQ(w[2].kind, WarpKind::Planar);
    EXPECT_EQ(w[2].planar_offset, 0.5);
    EXPECT_EQ(w[3].kind, WarpKind::Toroidal);
    EXPECT_EQ(w[3].major_radius, 2);
    EXPECT_EQ(w[4].kind, WarpKind::Spherical);
    EXPECT_EQ(w[5].kind, WarpKind::Cylindrical);
    EXPECT_EQ(w[5].orientation, Vec3(0, 1, 0));
    EXPECT_EQ(w[6].kind, WarpKind::BlackHole);
    EXPECT_EQ(w[6].radius, 0.5);
    EXPECT_EQ(w[6].strength, 2);
    EXPECT_EQ(w[6].falloff, 3);
    EXPECT_TRUE(w[6].inverse);
}

TEST(PovPatterns, MapsAndBlockEntries) {
    auto s = parse(
        "#declare CM = colour_map { [0 rgb 0] [1 rgb 1] }\n"
        "#declare PM = pigment_map { [0 rgb x] [1 granite] }\n"
        "sphere { 0, 1 pigment { bozo color_map { CM } } }\n"
        "sphere { 0, 1 pigment { wood pigment_map { PM } } }\n"
        "sphere { 0, 1 pigment { hexagon pigment { rgb x } pigment { rgb y } } }\n"
        "sphere { 0, 1 pigment { checker rgb x, rgb y } }\n"
        "sphere { 0, 1 pigment { average pigment_map { [1 rgb x] [ rgb y] [3 rgb z] } } }\n");
    EXPECT_EQ(texture_of(s, 0).pigment.color_map.size(), 2u);
    const auto& pm = texture_of(s, 1).pigment.pigment_map;
    ASSERT_EQ(pm.size(), 2u);
    EXPECT_EQ(pm[1].pigment[0].kind, PatternKind::Granite);
    const auto& hex = texture_of(s, 2).pigment.entries;
    ASSERT_EQ(hex.size(), 3u);
    EXPECT_EQ(hex[1].color.rgb, Color(0, 1, 0));
    EXPECT_EQ(hex[2].color.rgb, Color(0, 0, 0));  // the default pigment
    const auto& checker = texture_of(s, 3).pigment.entries;
    ASSERT_EQ(checker.size(), 2u);
    EXPECT_EQ(checker[1].color.rgb, Color(0, 1, 0));
    const auto& avg = texture_of(s, 4).pigment.pigment_map;
    ASSERT_EQ(avg.size(), 3u);
    EXPECT_EQ(avg[1].value, 1);  // an average weight may be left out
    EXPECT_EQ(avg[2].value, 3);
}

TEST(PovPatterns, NormalsAmountsAndMaps) {
    auto s = parse(
        "sphere { 0, 1 normal { bumps } }\n"
        "sphere { 0, 1 normal { dents 0.3 scale 0.1 accuracy 0.01 } }\n"
        "sphere { 0, 1 normal { granite bump_size 2 slope_map { [0 <0, 1>] [1 <1, 0>] } } }\n"
        "sphere { 0, 1 normal { gradient x normal_map { [0 bumps 0.2] [1 waves] } } }\n"
        "sphere { 0, 1 normal { checker normal { wrinkles } normal { ripples 0.1 } } }\n");
    EXPECT_EQ(texture_of(s, 0).normal.amount, 0.5);  // POV-Ray's default
    const auto& dents = texture_of(s, 1).normal;
    EXPECT_EQ(dents.amount, 0.3);
    EXPECT_EQ(dents.accuracy, 0.01);
    const auto& granite = texture_of(s, 2).normal;
    EXPECT_EQ(granite.amount, 2);
    ASSERT_EQ(granite.slope_map.size(), 2u);
    EXPECT_EQ(granite.slope_map[0].slope, 1);
    EXPECT_EQ(granite.slope_map[1].height, 1);
    const auto& nm = texture_of(s, 3).normal.normal_map;
    ASSERT_EQ(nm.size(), 2u);
    EXPECT_EQ(nm[0].normal[0].amount, 0.2);
    EXPECT_EQ(nm[1].normal[0].kind, PatternKind::Waves);
    const auto& blocks = texture_of(s, 4).normal.entries;
    ASSERT_EQ(blocks.size(), 2u);
    EXPECT_EQ(blocks[1].amount, 0.1);
}

TEST(PovPatterns, PatternedAndLayeredTextures) {
    auto s = parse(
        "#declare L = texture { pigment { rgb 1 } } texture { pigment { rgbt 0.5 } }\n"
        "sphere { 0, 1 texture { gradient y texture_map { [0 L] [1 pigment { rgb x }] } "
        "scale 2 } }\n"
        "sphere { 0, 1 texture { checker texture { pigment { rgb y } } texture { L } } }\n"
        "sphere { 0, 1 texture { L } texture { pigment { rgbf 0.3 } } }\n");
    const auto& g = texture_of(s, 0);
    EXPECT_EQ(g.kind, PatternKind::Gradient);
    EXPECT_EQ(g.transform.point(Vec3(1, 1, 1)), Vec3(2, 2, 2));
    ASSERT_EQ(g.texture_map.size(), 2u);
    EXPECT_EQ(g.texture_map[0].texture[0].layers.size(), 1u);
    const auto& c = texture_of(s, 1);
    ASSERT_EQ(c.entries.size(), 2u);
    EXPECT_EQ(c.entries[0].pigment.color.rgb, Color(0, 1, 0));
    const auto& layered = texture_of(s, 2);
    ASSERT_EQ(layered.layers.size(), 2u);
    EXPECT_EQ(layered.layers[1].pigment.color.filter, 0.3);
}

TEST(PovPatterns, TilesIsACheckerOfTwoTexturesWithTheFirstInTheSecondCell) {
    auto s = parse(
        "sphere { 0, 1 texture { tiles { texture { pigment { rgb x } } tile2\n"
        "  texture { pigment { rgb y } } texture { pigment { rgbt <0, 0, 1, 0.5> } } }\n"
        "  scale 2 } }\n"
        "sphere { 0, 1 texture { tiles { texture { pigment { rgb z } } tile2 } } }\n");
    const auto& t = texture_of(s, 0);
    EXPECT_EQ(t.kind, PatternKind::Checker);
    EXPECT_EQ(t.transform.point(Vec3(1, 1, 1)), Vec3(2, 2, 2));
    ASSERT_EQ(t.entries.size(), 2u);
    // Parse_Tiles: the first texture is the checker's entry 1, tile2's entry 0.
    EXPECT_EQ(t.entries[1].pigment.color.rgb, Color(1, 0, 0));
    EXPECT_EQ(t.entries[0].pigment.color.rgb, Color(0, 1, 0));
    ASSERT_EQ(t.entries[0].layers.size(), 1u);  // tile2's two textures are layered
    EXPECT_EQ(t.entries[0].layers[0].pigment.color.transmit, 0.5);
    const auto& empty_tile2 = texture_of(s, 1);
    ASSERT_EQ(empty_tile2.entries.size(), 2u);
    EXPECT_EQ(empty_tile2.entries[1].pigment.color.rgb, Color(0, 0, 1));
    EXPECT_EQ(error_of("sphere { 0, 1 texture { tiles { tile2 texture { } } } }"),
              "1:31: first texture missing from tiles");
    EXPECT_EQ(error_of("sphere { 0, 1 texture { tiles { texture { } } } }"),
              "1:45: expected tile2 in tiles, got '}'");
}

TEST(PovPatterns, MisuseIsAnErrorAtItsPlace) {
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { checker color_map { [0 rgb 0] } } }"),
              "1:33: cannot use color_map with the 'checker' pattern");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { bozo brick_size 2 } }"),
              "1:30: 'brick_size' applies only to brick patterns");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { facets } }"),
              "1:25: 'facets' can only be used in a normal");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { bozo bump_size 2 } }"),
              "1:30: 'bump_size' can only be used in a normal");
    EXPECT_EQ(error_of("sphere { 0, 1 normal { bumps color_map { [0 rgb 0] } } }"),
              "1:30: 'color_map' cannot be used in a normal");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { average } }"),
              "1:33: an average pigment needs a pigment_map");
    EXPECT_EQ(error_of("sphere { 0, 1 texture { bozo } }"),
              "1:30: a patterned texture needs a texture_map");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { bozo warp { twist } } }"),
              "1:37: expected a warp type (turbulence, repeat, black_hole, cylindrical, "
              "spherical, toroidal, planar, cubic), got 'twist'");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { bozo warp { repeat <1, 1, 0> } } }"),
              "1:44: a repeat warp repeats along one axis only");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { bozo noise_generator 4 } }"),
              "1:46: noise_generator must be 0, 1, 2 or 3");
    EXPECT_EQ(error_of("#declare M = normal_map { [0 bumps] }\n"
                       "sphere { 0, 1 pigment { bozo color_map { M } } }"),
              "2:42: expected a color_map, got a normal_map 'M'");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { bozo pigment_map { } } }"),
              "1:44: a pigment_map needs at least one entry");
    EXPECT_EQ(error_of("sphere { 0, 1 texture { bozo texture_map { [0 pigment { rgb 1 }] } }"
                       " texture { pigment { rgb 1 } } }"),
              "1:70: cannot layer over a patterned texture");
}

}  // namespace
}  // namespace glint::pov
