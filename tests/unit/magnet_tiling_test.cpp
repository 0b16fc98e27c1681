// The magnet and tiling patterns (render/textures/fractal_patterns.cpp, tiling_pattern.cpp)
// against the values POV-Ray 3.7 gives, and how the POV parser reads them (pattern_grammar.cpp).
// The references come from POV-Ray evaluating each pattern in a function at parse time
// (`#debug str(F(x, y, z), 0, 17)`); the tiling ones went through a pigment_pattern's float
// color map, so they hold to single precision only.
#include <gtest/gtest.h>

#include <array>
#include <utility>

#include "render/textures/pattern.h"
#include "tests/unit/pov_test_util.h"

namespace glint {
namespace {

using scene::PatternKind;
using scene::PatternParams;

const std::array<Vec3, 6> kPoints = {Vec3(0.3, 0.2, 0.1),  Vec3(-1.2, 0.7, 0),
                                     Vec3(1.7, -0.4, 0.5), Vec3(2.9, 1.1, -2.3),
                                     Vec3(0.05, 1.45, 0.8), Vec3(-0.61, -0.33, 1.9)};

void expect_values(PatternKind kind, const PatternParams& pp, const std::array<double, 6>& want,
                   double tolerance, const char* what) {
    const render::PatternContext ctx;
    for (size_t i = 0; i < kPoints.size(); ++i) {
        EXPECT_NEAR(render::evaluate_pattern(kind, pp, kPoints[i], ctx), want[i], tolerance)
            << what << " at point " << i;
    }
}

PatternParams magnet(int type, bool julia, int iterations) {
    PatternParams pp;
    pp.magnet_type = type;
    pp.magnet_julia = julia;
    pp.iterations = iterations;
    return pp;
}

TEST(MagnetPattern, MatchesPovRay) {
    // magnet 1 mandel 50
    expect_values(PatternKind::Magnet, magnet(1, false, 50), {1.0, 0.06, 0.1, 0.2, 0.08, 0.1},
                  1e-12, "magnet 1 mandel");
    // magnet 1 julia <0.4, -0.3>, 40 interior 1, 2 exterior 6, 0.01
    PatternParams j1 = magnet(1, true, 40);
    j1.julia_param = Vec2(0.4, -0.3);
    j1.interior_type = 1;
    j1.interior_factor = 2;
    j1.exterior_type = 6;
    j1.exterior_factor = 0.01;
    expect_values(PatternKind::Magnet, j1,
                  {0.52926302142247894, 0.21484857491157636, 0.01000447705361637,
                   0.43355485901712498, 0.25362797945837828, 0.02793802118548570},
                  1e-12, "magnet 1 julia");
    // magnet 2 mandel 300 interior 1, 1
    PatternParams m2 = magnet(2, false, 300);
    m2.interior_type = 1;
    expect_values(PatternKind::Magnet, m2,
                  {0.31999423025407475, 1.0 / 300, 0.02, 2.0 / 300, 0.01, 2.0 / 300}, 1e-12,
                  "magnet 2 mandel");
    // magnet 2 julia <1.2, 0.5>, 30 exterior 3, 0.5
    PatternParams j2 = magnet(2, true, 30);
    j2.julia_param = Vec2(1.2, 0.5);
    j2.exterior_type = 3;
    j2.exterior_factor = 0.5;
    expect_values(PatternKind::Magnet, j2,
                  {1.0, 1.0, 0.00493926710607191, 0.99999889781395013, 1.0, 1.0}, 1e-12,
                  "magnet 2 julia");
}

TEST(TilingPattern, MatchesPovRay) {
    const std::array<std::array<double, 6>, 5> want = {{
        {0.8, 1.0, 0.4, 0.8, 0.9, 0.8},
        {0.88452994823455811, 0.2, 0.58867514133453369, 0.77209436893463135,
         0.48811978101730347, 0.48696550726890564},
        {0.32679492235183716, 0.5, 0.48301270604133606, 0.15814156830310822,
         0.88564062118530273, 0.20910346508026123},
        {0.76905989646911621, 1.0, 0.17735026776790619, 0.54418873786926270,
         0.84752088785171509, 0.61213797330856323},
        {0.25635328888893127, 0.53333336114883423, 0.65911674499511719, 0.51472955942153931,
         0.39207985997200012, 0.87071263790130615},
    }};
    for (int n = 1; n <= 5; ++n) {
        PatternParams pp;
        pp.tiling_type = n;
        expect_values(PatternKind::Tiling, pp, want[n - 1], 1e-6,
                      ("tiling " + std::to_string(n)).c_str());
    }
    const std::pair<int, std::array<double, 6>> more[] = {
        {6, {0.89999997615814209, 0.5, 0.0, 0.20000000298023224, 0.94999998807907104,
             0.40000000596046448}},
        {7, {0.5, 0.99289321899414062, 0.65147185325622559, 0.5, 0.59289324283599854,
             0.58783227205276489}},
        {10, {0.8, 1.0, 0.4, 0.4, 0.9, 0.8}},
    };
    for (const auto& [n, values] : more) {
        PatternParams pp;
        pp.tiling_type = n;
        expect_values(PatternKind::Tiling, pp, values, 1e-6,
                      ("tiling " + std::to_string(n)).c_str());
    }
}

const scene::PatternParams& pigment_params(const scene::Scene& s) {
    return s.materials[s.objects[0].material].texture.pigment.params;
}

TEST(MagnetPattern, ParsesTypeFormConstantAndIterations) {
    auto s = pov::testing::parse(
        "sphere { 0, 1 pigment { magnet 2 julia <0.3, -0.2>, 25 interior 1, 3 } }");
    const auto& m = s.materials[s.objects[0].material].texture.pigment;
    EXPECT_EQ(m.kind, PatternKind::Magnet);
    EXPECT_EQ(m.params.magnet_type, 2);
    EXPECT_TRUE(m.params.magnet_julia);
    EXPECT_EQ(m.params.julia_param, Vec2(0.3, -0.2));
    EXPECT_EQ(m.params.iterations, 25);
    EXPECT_EQ(m.params.interior_type, 1);
    EXPECT_EQ(m.params.interior_factor, 3);
    EXPECT_EQ(m.params.exterior_type, 1);

    auto mm = pov::testing::parse("sphere { 0, 1 pigment { magnet 1 mandel 60 } }");
    EXPECT_EQ(pigment_params(mm).magnet_type, 1);
    EXPECT_FALSE(pigment_params(mm).magnet_julia);
    EXPECT_EQ(pigment_params(mm).iterations, 60);
}

TEST(MagnetPattern, MisuseIsAnError) {
    EXPECT_NE(pov::testing::error_of("sphere { 0, 1 pigment { magnet 3 mandel 20 } }")
                  .find("magnet mandel type must be 1 or 2"),
              std::string::npos);
    EXPECT_NE(pov::testing::error_of("sphere { 0, 1 pigment { magnet 1 bozo 20 } }")
                  .find("'mandel' or 'julia'"),
              std::string::npos);
    // POV-Ray allows no exponent on magnet.
    EXPECT_NE(pov::testing::error_of("sphere { 0, 1 pigment { magnet 1 mandel 20 exponent 3 } }")
                  .find("'exponent' applies only to mandel and julia"),
              std::string::npos);
}

TEST(TilingPattern, ParsesItsNumberAndRejectsOthers) {
    auto s = pov::testing::parse("sphere { 0, 1 pigment { tiling 4.7 } }");
    EXPECT_EQ(s.materials[s.objects[0].material].texture.pigment.kind, PatternKind::Tiling);
    EXPECT_EQ(pigment_params(s).tiling_type, 4);
    EXPECT_NE(pov::testing::error_of("sphere { 0, 1 pigment { tiling 28 } }")
                  .find("tiling number must be 1 to 27"),
              std::string::npos);
}

}  // namespace
}  // namespace glint
