// POV-Ray's own standard includes and six of its example scenes must parse into the IR we
// expect; the expected numbers are worked out by hand from the scene text (comments show how).
// Scenes come from tests/data/pov-examples; those that #include POV-Ray's standard files
// need /usr/share/povray-3.7/include and are skipped without it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "tests/unit/pov_test_util.h"

namespace glint::pov {
namespace {

namespace fs = std::filesystem;
using testing::povray_include_dir;

const std::string kExamples = std::string(GLINT_SOURCE_DIR) + "/tests/data/pov-examples/";

scene::Scene load(const std::string& rel) {
    ParseOptions o;
    if (!povray_include_dir().empty()) o.include_dirs.push_back(povray_include_dir());
    Diagnostics diag;
    return parse_file(kExamples + rel, o, diag);
}

#define NEED_INCLUDES()                                                      \
    if (povray_include_dir().empty()) GTEST_SKIP() << "POV-Ray includes absent"

void expect_near(const Vec3& a, const Vec3& b, double tol = 1e-5) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

const scene::Material& mat(const scene::Scene& s, const scene::Object& o) {
    return s.materials.at(o.material);
}

TEST(PovStandardIncludes, ColorsCharsMetalsParseAndWork) {
    NEED_INCLUDES();
    ParseOptions o;
    o.include_dirs.push_back(povray_include_dir());
    Diagnostics diag;
    auto s = parse_string(
        "#include \"colors.inc\"\n#include \"chars.inc\"\n#include \"metals.inc\"\n"
        "sphere { 0, 1 texture { T_Gold_1A } }\n"
        "sphere { 0, 1 pigment { CHSV2RGB(<120, 1, 1>) } }\n"
        "object { char_A pigment { SteelBlue } }\n",
        (fs::current_path() / "t.pov").string(), o, diag);
    ASSERT_EQ(s.objects.size(), 3u);
    // golds.inc: P_Gold1 = <1, 0.875, 0.575> - <0, 0.2, 0.4> = <1, 0.675, 0.175>;
    // A_GoldA = P_Gold1 * 0.12 + 0.1; F_MetalA (golds version): brilliance 2, specular 0.2.
    const auto& t = mat(s, s.objects[0]).texture;
    EXPECT_NEAR(t.pigment.color.rgb.g, 0.675, 1e-12);
    EXPECT_NEAR(t.finish.ambient.g, 0.675 * 0.12 + 0.1, 1e-12);
    EXPECT_EQ(t.finish.brilliance, 2);
    EXPECT_EQ(t.finish.specular, 0.2);
    EXPECT_EQ(t.finish.metallic, 1);
    EXPECT_NEAR(t.finish.roughness, 1.0 / 20, 1e-15);
    // CHSV2RGB(<120,1,1>) = pure green (colors.inc macros with #switch/#range).
    const auto& g = mat(s, s.objects[1]).texture.pigment.color.rgb;
    EXPECT_NEAR(g.r, 0, 1e-12);
    EXPECT_NEAR(g.g, 1, 1e-12);
    EXPECT_NEAR(g.b, 0, 1e-12);
    // colors.inc: SteelBlue = color red 0.137255 green 0.576471 blue 0.650980
    EXPECT_NEAR(mat(s, s.objects[2]).texture.pigment.color.rgb.r, 0.137255, 1e-12);
    EXPECT_EQ(s.version, 3.7) << "the includes restore the #version they found";
}

TEST(PovStandardIncludes, PatternTexturesAreUsable) {
    NEED_INCLUDES();
    ParseOptions o;
    o.include_dirs.push_back(povray_include_dir());
    // textures.inc and glass.inc declare pattern, layered and glass textures; all of them
    // parse now, and a pattern texture such as Jade is usable.
    Diagnostics diag;
    auto s = parse_string(
        "#include \"colors.inc\"\n#include \"textures.inc\"\n#include \"glass.inc\"\n"
        "sphere { 0, 1 texture { Chrome_Metal } }\n"
        "sphere { 0, 1 texture { Jade } }\n",
        (fs::current_path() / "t.pov").string(), o, diag);
    ASSERT_EQ(s.objects.size(), 2u);
    const scene::Material& jade = s.materials[s.objects[1].material];
    EXPECT_EQ(jade.texture.pigment.kind, scene::PatternKind::Marble);
}

TEST(PovExamples, Perspective) {
    NEED_INCLUDES();
    auto s = load("camera/perspective.pov");
    EXPECT_EQ(s.objects.size(), 6u);  // box, four Cubes objects, sphere
    // right = x*320/240; |direction| = (4/3)/tan(25 deg)/2 along look_at - location =
    // (-35, 9, -22)/sqrt(1790).
    double dl = (4.0 / 3.0) / std::tan(25 * kPi / 180) / 2;
    double n = std::sqrt(1790.0);
    expect_near(s.camera.direction, Vec3(-35, 9, -22) * (dl / n));
    // right = normalize(sky x dir) * 4/3 = normalize(<-22, 0, 35>) * 4/3.
    double rn = std::sqrt(22.0 * 22 + 35 * 35);
    expect_near(s.camera.right, Vec3(-22, 0, 35) * (4.0 / 3.0 / rn));
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].color, Color(2, 2, 2));  // White*2
    ASSERT_TRUE(s.sky_sphere.has_value());
    // The box: checker White, Gray90 scale 5, reflection {.1}.
    const auto& box = mat(s, s.objects[0]).texture;
    EXPECT_EQ(box.pigment.kind, scene::PatternKind::Checker);
    EXPECT_NEAR(box.pigment.entries.at(1).color.rgb.r, 0.9, 1e-12);
    EXPECT_EQ(box.pigment.transform.point(Vec3(1, 1, 1)), Vec3(5, 5, 5));
    EXPECT_NEAR(box.finish.reflection.max.r, 0.1, 1e-12);
    // Cubes1 is a union of three boxes, each with its own pigment, moved by <5,0,-5>.
    const auto& cubes1 = std::get<scene::Csg>(s.objects[1].shape);
    ASSERT_EQ(cubes1.children.size(), 3u);
    EXPECT_GE(cubes1.children[0].material, 0);
    EXPECT_EQ(s.objects[1].transform.point(Vec3(0, 0, 0)), Vec3(5, 0, -5));
}

TEST(PovExamples, Atten1) {
    NEED_INCLUDES();
    auto s = load("interior/atten1.pov");
    EXPECT_EQ(s.camera.kind, scene::CameraKind::Orthographic);
    expect_near(s.camera.right, {80 * 4.0 / 3.0, 0, 0});
    expect_near(s.camera.up, {0, 80, 0});
    ASSERT_EQ(s.objects.size(), 5u);
    for (int i = 1; i <= 4; ++i) {
        const auto& m = mat(s, s.objects[i]);
        EXPECT_EQ(m.interior.ior, 1.05);
        EXPECT_EQ(m.interior.fade_distance, 20);
        EXPECT_EQ(m.interior.fade_power, i - 1);
        EXPECT_EQ(m.texture.pigment.color.transmit, 0.9);
        EXPECT_EQ(m.texture.finish.phong_size, 200);
    }
    EXPECT_EQ(std::get<scene::Plane>(s.objects[0].shape).normal, Vec3(0, 0, -1));
    EXPECT_EQ(std::get<scene::Plane>(s.objects[0].shape).distance, -20);
}

TEST(PovExamples, ParallelLights) {
    NEED_INCLUDES();
    auto s = load("lights/parallel_lights.pov");
    EXPECT_EQ(s.version, 3.6);
    EXPECT_EQ(s.objects.size(), 7u);  // #while I = -20, -12, -4, 4, 12: five boxes, two planes
    EXPECT_EQ(std::get<scene::Box>(s.objects[4].shape).corner1, Vec3(0, 50, 12));
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_TRUE(s.lights[0].parallel);
    EXPECT_EQ(s.lights[0].point_at, Vec3(10, 0, 20));
    EXPECT_EQ(s.lights[0].color, Color(1.5, 1.5, 1.5));
    EXPECT_FALSE(s.lights[1].parallel);
}

TEST(PovExamples, Sombrero) {
    auto s = load("advanced/sombrero.pov");
    // Zc and Xc run from -1 to 1 in steps of 1/16: 33 unions of 33 spheres.
    ASSERT_EQ(s.objects.size(), 33u);
    const auto& row = std::get<scene::Csg>(s.objects[0].shape);
    ASSERT_EQ(row.children.size(), 33u);
    EXPECT_NEAR(s.background.rgb.r, 0.09, 1e-12);
    // First sphere: Xc = Zc = -1, YHeight = sin(sqrt(2)*6.28*2).
    double yh = std::sin(std::sqrt(2.0) * 6.28 * 2);
    const auto& sp = row.children[0];
    expect_near(sp.transform.point(Vec3(0, 0, 0)), {-1, yh / 4, -1}, 1e-12);
    const auto& t = mat(s, sp).texture;
    EXPECT_NEAR(t.pigment.color.rgb.r, (-0.5 + 1) * yh, 1e-12);
    EXPECT_EQ(t.finish.ambient, Color(0.2, 0.2, 0.2));
    EXPECT_NEAR(t.finish.reflection.max.g, 0.2, 1e-12);
}

TEST(PovExamples, Chars) {
    NEED_INCLUDES();
    auto s = load("incdemo/chars.pov");
    ASSERT_EQ(s.objects.size(), 51u);  // the plane and 50 characters
    EXPECT_TRUE(s.objects[0].hollow);
    // #default { pigment { Cyan } } reaches the characters declared before it.
    for (size_t i = 1; i < s.objects.size(); ++i)
        EXPECT_EQ(mat(s, s.objects[i]).texture.pigment.color.rgb, Color(0, 1, 1)) << i;
    EXPECT_EQ(s.objects[1].name, "char_A");
    EXPECT_EQ(s.objects[1].transform.point(Vec3(0, 0, 0)), Vec3(-22, 18, 0));
    EXPECT_EQ(s.objects[1].bounded_by.size(), 1u);
}

TEST(PovExamples, Mapper) {
    NEED_INCLUDES();
    auto s = load("textures/pigments/mapper.pov");
    ASSERT_EQ(s.objects.size(), 2u);
    const auto& sphere = mat(s, s.objects[0]).texture.pigment;
    EXPECT_EQ(sphere.kind, scene::PatternKind::ImageMap);
    EXPECT_EQ(sphere.params.image.map_type, 1);
    EXPECT_EQ(sphere.params.image.interpolate, 2);
    EXPECT_TRUE(fs::exists(sphere.params.image.resolved_path));
    const auto& plane = mat(s, s.objects[1]).texture.pigment;
    EXPECT_TRUE(plane.params.image.once);
    EXPECT_EQ(s.objects[1].clipped_by.size(), 1u);
    EXPECT_TRUE(s.objects[1].hollow);
}

TEST(PovExamples, GlintScenesParse) {
    NEED_INCLUDES();
    fs::path dir = fs::path(GLINT_SOURCE_DIR) / "scenes";
    if (!fs::is_directory(dir)) GTEST_SKIP() << "no scenes/ folder";
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        if (e.path().extension() != ".pov") continue;
        ParseOptions o;
        o.include_dirs.push_back(povray_include_dir());
        Diagnostics diag;
        EXPECT_NO_THROW(parse_file(e.path().string(), o, diag)) << e.path();
        ++n;
    }
    EXPECT_GT(n, 0);
}

}  // namespace
}  // namespace glint::pov
