// Pattern evaluation against POV-Ray 3.7: values POV-Ray itself produced for each pattern,
// warp and special normal (16-bit renders of a plane, read back linearly), plus exact
// properties (block indices, ranges, determinism).
#include "render/textures/pattern.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>

namespace glint::render {
namespace {

using scene::PatternKind;
using scene::PatternParams;
using scene::Warp;
using scene::WarpKind;

#include "unit/pattern_pov_cases.inc"  // Sample, PovCase, kPovCases, kPovNormalCases

struct Spec {
    PatternKind kind = PatternKind::Plain;
    PatternParams params;
    bool normal = false;
    double amount = 0.5;
};

Vec3 parse_vec(const std::string& v) {
    Vec3 r;
    std::sscanf(v.c_str(), "%lf,%lf,%lf", &r.x, &r.y, &r.z);
    return r;
}

// The cases above name their POV-Ray parameters compactly; this turns them into the IR.
Spec parse_spec(const std::string& text) {
    static const std::map<std::string, PatternKind> kKinds = {
        {"agate", PatternKind::Agate},
        {"boxed", PatternKind::Boxed},
        {"bozo", PatternKind::Bozo},
        {"bumps", PatternKind::Bumps},
        {"cells", PatternKind::Cells},
        {"crackle", PatternKind::Crackle},
        {"cylindrical", PatternKind::Cylindrical},
        {"dents", PatternKind::Dents},
        {"granite", PatternKind::Granite},
        {"leopard", PatternKind::Leopard},
        {"marble", PatternKind::Marble},
        {"onion", PatternKind::Onion},
        {"planar", PatternKind::Planar},
        {"quilted", PatternKind::Quilted},
        {"radial", PatternKind::Radial},
        {"ripples", PatternKind::Ripples},
        {"spherical", PatternKind::Spherical},
        {"spiral1", PatternKind::Spiral1},
        {"spiral2", PatternKind::Spiral2},
        {"spotted", PatternKind::Spotted},
        {"waves", PatternKind::Waves},
        {"wood", PatternKind::Wood},
        {"wrinkles", PatternKind::Wrinkles},
        {"brick", PatternKind::Brick},
        {"hexagon", PatternKind::Hexagon},
        {"square", PatternKind::Square},
        {"triangular", PatternKind::Triangular},
        {"cubic", PatternKind::Cubic},
        {"checker", PatternKind::Checker},
        {"gradient", PatternKind::Gradient},
        {"mandel", PatternKind::Mandel},
        {"julia", PatternKind::Julia},
        {"facets", PatternKind::Facets}};
    Spec s;
    std::istringstream in(text);
    std::string word;
    in >> word;
    s.kind = kKinds.at(word);
    PatternParams& pp = s.params;
    auto add_warp = [&pp](WarpKind kind) -> Warp& {
        Warp w;
        w.kind = kind;
        pp.warps.push_back(w);
        return pp.warps.back();
    };
    while (in >> word) {
        auto eq = word.find('=');
        std::string k = word.substr(0, eq);
        std::string v = eq == std::string::npos ? "" : word.substr(eq + 1);
        if (k == "normal") {
            s.normal = true;
            s.amount = std::stod(v);
        } else if (k == "turb") {
            add_warp(WarpKind::ClassicTurbulence).turbulence.amount = parse_vec(v);
        } else if (k == "wturb") {
            add_warp(WarpKind::Turbulence).turbulence.amount = parse_vec(v);
        } else if (k == "octaves") {
            pp.warps.back().turbulence.octaves = std::stoi(v);
        } else if (k == "omega") {
            pp.warps.back().turbulence.omega = std::stod(v);
        } else if (k == "lambda") {
            pp.warps.back().turbulence.lambda = std::stod(v);
        } else if (k == "freq") {
            pp.frequency = std::stod(v);
        } else if (k == "phase") {
            pp.phase = std::stod(v);
        } else if (k == "wave") {
            pp.wave = static_cast<scene::WaveType>(std::stoi(v));
        } else if (k == "gen") {
            pp.noise_generator = std::stoi(v);
        } else if (k == "arms") {
            pp.arms = std::stoi(v);
        } else if (k == "mortar") {
            pp.mortar = std::stod(v);
        } else if (k == "brick_size") {
            pp.brick_size = parse_vec(v);
        } else if (k == "metric") {
            pp.crackle_metric = std::stod(v);
        } else if (k == "offset") {
            pp.crackle_offset = std::stod(v);
        } else if (k == "solid") {
            pp.crackle_solid = true;
        } else if (k == "form") {
            pp.crackle_form = parse_vec(v);
        } else if (k == "c0") {
            pp.control0 = std::stod(v);
        } else if (k == "c1") {
            pp.control1 = std::stod(v);
        } else if (k == "agate_turb") {
            pp.agate_turb = std::stod(v);
        } else if (k == "iter") {
            pp.iterations = std::stoi(v);
        } else if (k == "exp") {
            pp.fractal_exponent = std::stod(v);
        } else if (k == "julia") {
            std::sscanf(v.c_str(), "%lf,%lf", &pp.julia_param.x, &pp.julia_param.y);
        } else if (k == "ext") {
            std::sscanf(v.c_str(), "%d,%lf", &pp.exterior_type, &pp.exterior_factor);
        } else if (k == "int") {
            std::sscanf(v.c_str(), "%d,%lf", &pp.interior_type, &pp.interior_factor);
        } else if (k == "vector") {
            pp.vector = parse_vec(v);
        } else if (k == "repeat") {
            add_warp(WarpKind::Repeat).direction = parse_vec(v);
        } else if (k == "roffset") {
            pp.warps.back().offset = parse_vec(v);
        } else if (k == "rflip") {
            pp.warps.back().flip = parse_vec(v);
        } else if (k == "bh") {
            Warp& w = add_warp(WarpKind::BlackHole);
            std::sscanf(v.c_str(), "%lf,%lf,%lf,%lf", &w.center.x, &w.center.y, &w.center.z,
                        &w.radius);
        } else if (k == "bhstrength") {
            pp.warps.back().strength = std::stod(v);
        } else if (k == "bhfalloff") {
            pp.warps.back().falloff = std::stod(v);
        } else if (k == "bhrepeat") {
            pp.warps.back().repeat = parse_vec(v);
        } else if (k == "bhturb") {
            pp.warps.back().turbulence.amount = parse_vec(v);
        } else if (k == "wcyl") {
            add_warp(WarpKind::Cylindrical).orientation = parse_vec(v);
        } else if (k == "wsph") {
            add_warp(WarpKind::Spherical).orientation = parse_vec(v);
        } else if (k == "wtor") {
            add_warp(WarpKind::Toroidal).orientation = parse_vec(v);
        } else if (k == "wplanar") {
            add_warp(WarpKind::Planar).orientation = parse_vec(v);
        } else if (k == "distexp") {
            pp.warps.back().dist_exp = std::stod(v);
        } else if (k == "major") {
            pp.warps.back().major_radius = std::stod(v);
        } else if (k == "poffset") {
            pp.warps.back().planar_offset = std::stod(v);
        } else if (k == "wcubic") {
            add_warp(WarpKind::Cubic);
        } else if (k == "facets_size") {
            pp.facets_size = std::stod(v);
        } else if (k == "facets_coords") {
            pp.facets_coords = std::stod(v);
        } else {
            ADD_FAILURE() << "unknown spec key " << k;
        }
    }
    return s;
}

// 16-bit output: half a step of 1/65535 plus the rounding of POV-Ray's own transform.
constexpr double kPovTolerance = 2.5e-5;

TEST(PatternPov, ValuesMatchPovRay) {
    const PatternContext ctx;
    for (const PovCase& c : kPovCases) {
        Spec s = parse_spec(c.spec);
        for (const Sample& smp : c.samples) {
            double v = evaluate_pattern(s.kind, s.params, smp.p, ctx);
            if (c.block) {
                EXPECT_EQ(v, smp.value) << c.name << " at " << smp.p.x << "," << smp.p.y;
            } else {
                // A color_map clamps the value to its first and last entries.
                EXPECT_NEAR(std::clamp(v, 0.0, 1.0), smp.value, kPovTolerance)
                    << c.name << " at " << smp.p.x << "," << smp.p.y << "," << smp.p.z;
            }
        }
    }
}

TEST(PatternPov, SpecialNormalsMatchPovRay) {
    const PatternContext ctx;
    const Vec3 travel = normalize(Vec3(0.3, 0.5, 1.0));
    for (const PovCase& c : kPovNormalCases) {
        Spec s = parse_spec(c.spec);
        ASSERT_TRUE(s.normal) << c.name;
        ASSERT_TRUE(has_special_normal(s.kind)) << c.name;
        for (const Sample& smp : c.samples) {
            Vec3 n = special_normal(s.kind, s.params, smp.p, Vec3(0, 0, -1), s.amount, ctx);
            EXPECT_NEAR(length(n), 1.0, 1e-12) << c.name;
            double lit = std::max(0.0, -dot(n, travel));
            EXPECT_NEAR(lit, smp.value, kPovTolerance)
                << c.name << " at " << smp.p.x << "," << smp.p.y;
        }
    }
}

TEST(Pattern, BlockPatternsGiveEntryIndices) {
    const PatternContext ctx;
    PatternParams pp;
    EXPECT_TRUE(is_block_pattern(PatternKind::Hexagon));
    EXPECT_FALSE(is_block_pattern(PatternKind::Bozo));
    // Checker parity of the summed floors.
    EXPECT_EQ(evaluate_pattern(PatternKind::Checker, pp, Vec3(0.5, 0.5, 0.5), ctx), 0.0);
    EXPECT_EQ(evaluate_pattern(PatternKind::Checker, pp, Vec3(1.5, 0.5, 0.5), ctx), 1.0);
    EXPECT_EQ(evaluate_pattern(PatternKind::Checker, pp, Vec3(-0.5, 0.5, 0.5), ctx), 1.0);
    // Hexagon: the hexagon at the origin is entry 0; the cube faces +x..-z are 0..5.
    EXPECT_EQ(evaluate_pattern(PatternKind::Hexagon, pp, Vec3(0.01, 0, 0.01), ctx), 0.0);
    const Vec3 faces[6] = {{1, 0.1, 0.2},  {0.1, 1, 0.2},  {0.1, 0.2, 1},
                           {-1, 0.1, 0.2}, {0.1, -1, 0.2}, {0.1, 0.2, -1}};
    for (int i = 0; i < 6; ++i)
        EXPECT_EQ(evaluate_pattern(PatternKind::Cubic, pp, faces[i], ctx), i);
    // Block patterns ignore frequency and waves (POV-Ray's parser sets their frequency to 0).
    pp.frequency = 3;
    pp.wave = scene::WaveType::Sine;
    EXPECT_EQ(evaluate_pattern(PatternKind::Square, pp, Vec3(1.5, 0, 0.5), ctx), 3.0);
    // Brick: mortar at the bottom of every course.
    PatternParams brick;
    EXPECT_EQ(evaluate_pattern(PatternKind::Brick, brick, Vec3(2, 0.0, 2), ctx), 0.0);
    EXPECT_EQ(evaluate_pattern(PatternKind::Brick, brick, Vec3(2, 1.5, 1), ctx), 1.0);
}

TEST(Pattern, WaveShapingAndFrequency) {
    const PatternContext ctx;
    PatternParams pp;
    pp.vector = Vec3(1, 0, 0);
    // Frequency/phase wrap with POV-Ray's 1.00001 modulus; negative values wrap into [0, 1).
    pp.frequency = 2;
    pp.phase = 0.1;
    EXPECT_NEAR(evaluate_pattern(PatternKind::Gradient, pp, Vec3(0.3, 0, 0), ctx), 0.7, 1e-12);
    EXPECT_NEAR(evaluate_pattern(PatternKind::Gradient, pp, Vec3(-0.3, 0, 0), ctx), 0.5, 1e-12);
    pp.frequency = 1;
    pp.phase = 0;
    pp.wave = scene::WaveType::Triangle;
    EXPECT_NEAR(evaluate_pattern(PatternKind::Gradient, pp, Vec3(0.75, 0, 0), ctx), 0.5, 1e-12);
    pp.wave = scene::WaveType::Sine;
    EXPECT_NEAR(evaluate_pattern(PatternKind::Gradient, pp, Vec3(0.25, 0, 0), ctx), 1.0, 1e-12);
    pp.wave = scene::WaveType::Cubic;
    EXPECT_NEAR(evaluate_pattern(PatternKind::Gradient, pp, Vec3(0.5, 0, 0), ctx), 0.5, 1e-12);
    pp.wave = scene::WaveType::Poly;
    pp.wave_exponent = 2;
    EXPECT_NEAR(evaluate_pattern(PatternKind::Gradient, pp, Vec3(0.5, 0, 0), ctx), 0.25, 1e-12);
}

TEST(Pattern, ContinuousPatternsStayInRange) {
    const PatternContext ctx;
    const PatternKind kinds[] = {PatternKind::Agate,   PatternKind::Bozo,   PatternKind::Cells,
                                 PatternKind::Crackle, PatternKind::Dents,  PatternKind::Leopard,
                                 PatternKind::Onion,   PatternKind::Radial, PatternKind::Ripples,
                                 PatternKind::Spotted, PatternKind::Waves,  PatternKind::Wrinkles,
                                 PatternKind::Quilted, PatternKind::Boxed,  PatternKind::Spherical};
    PatternParams pp;
    Warp turb;
    turb.kind = WarpKind::ClassicTurbulence;
    turb.turbulence.amount = Vec3(0.7, 0.7, 0.7);
    pp.warps.push_back(turb);
    for (PatternKind k : kinds) {
        for (int i = 0; i < 200; ++i) {
            Vec3 p(std::sin(i * 1.7) * 9, std::cos(i * 0.37) * 7 - 3, i * 0.123 - 12);
            double v = evaluate_pattern(k, pp, p, ctx);
            ASSERT_GE(v, 0.0) << scene::pattern_name(k);
            ASSERT_LE(v, 1.00001) << scene::pattern_name(k);
            ASSERT_EQ(v, evaluate_pattern(k, pp, p, ctx)) << "deterministic";
        }
    }
}

TEST(Pattern, WarpTransformAndRepeat) {
    const PatternContext ctx;
    PatternParams pp;
    pp.vector = Vec3(1, 0, 0);
    Warp w;
    w.kind = WarpKind::Transform;
    w.transform = Transform::scale(Vec3(2, 2, 2));
    pp.warps.push_back(w);
    // warp { scale 2 } stretches the pattern: the value at x = 1 is the unwarped one at 0.5.
    EXPECT_NEAR(evaluate_pattern(PatternKind::Gradient, pp, Vec3(1, 0, 0), ctx), 0.5, 1e-12);
    PatternParams rep;
    rep.vector = Vec3(1, 0, 0);
    Warp r;
    r.kind = WarpKind::Repeat;
    r.direction = Vec3(0.5, 0, 0);
    r.flip = Vec3(1, 0, 0);
    rep.warps.push_back(r);
    // Odd blocks are mirrored: x = 0.6 in block 1 reads x = 0.4 of block 0.
    EXPECT_NEAR(evaluate_pattern(PatternKind::Gradient, rep, Vec3(0.6, 0, 0), ctx), 0.4, 1e-12);
    EXPECT_NEAR(evaluate_pattern(PatternKind::Gradient, rep, Vec3(1.1, 0, 0), ctx), 0.1, 1e-12);
}

TEST(Pattern, HugeAndNonFiniteCoordinatesStayDefined) {
    // POV-Ray converts cell coordinates with (int) casts, undefined past the int range; the
    // block tables must never be indexed out of range there.
    const PatternContext ctx;
    PatternParams pp;
    const double big = 1e30, nan = std::nan("");
    const Vec3 points[] = {{big, -big, big}, {-big, 3, big}, {nan, 0, 0}, {1e17, 1e17, -1e17}};
    for (int k = static_cast<int>(PatternKind::Plain); k <= static_cast<int>(PatternKind::Average);
         ++k) {
        // image_pattern reads an image (the pigment tests give it one).
        if (static_cast<PatternKind>(k) == PatternKind::ImagePattern) continue;
        for (const Vec3& p : points) {
            double v = evaluate_pattern(static_cast<PatternKind>(k), pp, p, ctx);
            if (is_block_pattern(static_cast<PatternKind>(k)) && std::isfinite(p.x)) {
                EXPECT_GE(v, 0.0);
                EXPECT_LE(v, 5.0);
            }
        }
    }
}

TEST(Pattern, SpecialNormalIsUnitLengthInsideItsWarpTransforms) {
    // Warp_Normal normalizes the normal carried into the warped space, so the amount perturbs
    // a unit normal: `bumps 0.6 scale 0.025 warp { turbulence ... }` (the scale becomes a
    // transform warp before the turbulence) bumps as much as an unscaled one at the same
    // pattern point (a uniform scale leaves normal directions alone).
    const PatternContext ctx;
    PatternParams scaled;
    Warp w;
    w.kind = WarpKind::Transform;
    w.transform = Transform::scale(Vec3(0.025, 0.025, 0.025));
    scaled.warps.push_back(w);
    const PatternParams plain;
    const Vec3 n = normalize(Vec3(0.1, 1, -0.2));
    const Vec3 q(0.37, 1.21, -2.6);  // the point in pattern space
    for (PatternKind k : {PatternKind::Bumps, PatternKind::Quilted, PatternKind::Wrinkles}) {
        const Vec3 a = special_normal(k, scaled, q * 0.025, n, 0.6, ctx);
        const Vec3 b = special_normal(k, plain, q, n, 0.6, ctx);
        EXPECT_NEAR(a.x, b.x, 1e-9) << scene::pattern_name(k);
        EXPECT_NEAR(a.y, b.y, 1e-9);
        EXPECT_NEAR(a.z, b.z, 1e-9);
    }
}

TEST(Pattern, SpecialNormalWithoutPerturbationKeepsTheNormal) {
    const PatternContext ctx;
    PatternParams pp;
    const Vec3 n = normalize(Vec3(0.2, -0.3, 0.9));
    for (PatternKind k : {PatternKind::Bumps, PatternKind::Dents, PatternKind::Ripples,
                          PatternKind::Waves, PatternKind::Wrinkles, PatternKind::Quilted}) {
        Vec3 r = special_normal(k, pp, Vec3(0.3, 1.7, -2.2), n, 0.0, ctx);
        EXPECT_NEAR(r.x, n.x, 1e-12) << scene::pattern_name(k);
        EXPECT_NEAR(r.y, n.y, 1e-12);
        EXPECT_NEAR(r.z, n.z, 1e-12);
    }
    EXPECT_FALSE(has_special_normal(PatternKind::Bozo));
    EXPECT_TRUE(has_special_normal(PatternKind::Facets));
}

}  // namespace
}  // namespace glint::render
