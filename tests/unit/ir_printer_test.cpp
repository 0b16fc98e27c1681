// The IR printer: a hand-built scene printed to text with the lines written out by hand,
// plus the number formatting rules that keep the output stable.
#include <gtest/gtest.h>

#include "formats/common/ir_printer.h"

namespace glint::formats {
namespace {

using namespace glint::scene;

bool has_line(const std::string& text, const std::string& line) {
    return ("\n" + text).find("\n" + line + "\n") != std::string::npos;
}

Scene small_scene() {
    Scene s;
    s.version = 3.6;
    s.global.assumed_gamma = 1.0;
    s.camera.location = {0, 1, -5};
    s.lights.push_back(Light{});
    s.lights[0].location = {1, 2, 3};
    Material m;
    m.texture.pigment.color = ColorFT(Color(1, 0.5, 0), 0, 0.25);
    m.texture.finish.phong = 0.7;
    s.materials.push_back(m);
    Object sphere;
    sphere.shape = Sphere{{1, 2, 3}, 0.5};
    sphere.material = 0;
    sphere.hollow = true;
    Object box;
    box.shape = Box{{-1, -1, -1}, {1, 1, 1}};
    box.transform = Transform::translate({-0.0, 2, 0});
    Object u;
    u.shape = Csg{CsgOp::Difference, {box}};
    u.material = 0;
    s.objects = {sphere, u};
    return s;
}

TEST(IrPrinter, BlenderLightPrintsItsOwnFields) {
    Scene s = small_scene();
    BlenderLight b;
    b.type = BlenderLightType::Spot;
    b.power = 250;
    b.radius = 0.1;
    b.spot_size = 60;
    b.spot_blend = 0.5;
    b.visible_camera = true;
    s.lights[0].blender = b;
    std::string text = print_ir(s);
    EXPECT_TRUE(has_line(text, "  blender_light spot power 250 direction <0, -1, 0> radius 0.1 "
                               "spot_size 60 spot_blend 0.5 visible_camera"))
        << text;
}

TEST(IrPrinter, ReadableLines) {
    std::string text = print_ir(small_scene());
    EXPECT_TRUE(has_line(text, "version 3.6")) << text;
    EXPECT_TRUE(has_line(text,
                         "global_settings assumed_gamma 1 ambient_light rgb <1, 1, 1> "
                         "max_trace_level 5 adc_bailout 0.00392157 noise_generator 2"))
        << text;
    EXPECT_TRUE(has_line(text, "camera perspective")) << text;
    EXPECT_TRUE(has_line(text, "  location <0, 1, -5>")) << text;
    EXPECT_TRUE(has_line(text, "  right <1.33, 0, 0>")) << text;
    EXPECT_TRUE(has_line(text, "light 0 point location <1, 2, 3> color rgb <1, 1, 1>")) << text;
    EXPECT_TRUE(has_line(text, "material 0")) << text;
    EXPECT_TRUE(has_line(text, "  pigment rgbft <1, 0.5, 0, 0, 0.25>")) << text;
    EXPECT_TRUE(has_line(text,
                         "  finish ambient rgb <0.1, 0.1, 0.1> diffuse 0.6 brilliance 1 phong 0.7 "
                         "phong_size 40 specular 0 roughness 0.05 metallic 0"))
        << text;
    EXPECT_TRUE(has_line(text, "object 0 sphere <1, 2, 3> 0.5 material 0 hollow")) << text;
    EXPECT_TRUE(has_line(text, "object 1 difference (1 children) material 0")) << text;
    EXPECT_TRUE(has_line(text, "  box <-1, -1, -1> <1, 1, 1> material -1")) << text;
    EXPECT_TRUE(has_line(text, "    transform matrix [1 0 0 0; 0 1 0 2; 0 0 1 0]")) << text;
}

TEST(IrPrinter, StableAndDeterministic) {
    Scene s = small_scene();
    EXPECT_EQ(print_ir(s), print_ir(s));
    s.camera.location = {1.0 / 3.0, -0.0, 1e-20};
    std::string text = print_ir(s);
    EXPECT_TRUE(has_line(text, "  location <0.333333, 0, 1e-20>")) << text;
}

TEST(IrPrinter, LocationsAreShown) {
    Scene s;
    Object o;
    o.shape = Sphere{};
    o.material = 0;
    o.loc = FileLoc{std::make_shared<const std::string>("a.pov"), 3, 7};
    s.objects.push_back(o);
    EXPECT_TRUE(has_line(print_ir(s), "object 0 sphere <0, 0, 0> 1 material 0  @a.pov:3:7"));
}

}  // namespace
}  // namespace glint::formats
