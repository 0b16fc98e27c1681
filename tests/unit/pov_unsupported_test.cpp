// Features glint lacks: one warning per feature naming it and where it was first met; the
// object or effect is read over and left out, and the rest of the scene is kept.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/log.h"
#include "formats/pov/parser.h"
#include "scene/scene.h"

namespace {

struct Parsed {
    glint::scene::Scene scene;
    std::vector<std::string> warnings;  // "line:col: message"
};

Parsed parse_warn(const std::string& text) {
    Parsed r;
    glint::Diagnostics diag([&r](const glint::Diagnostic& d) {
        if (d.level == glint::Diagnostic::Level::Warning && d.loc.line > 0)
            r.warnings.push_back(std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) +
                                 ": " + d.message);
    });
    r.scene = glint::pov::parse_string("#version 3.7;\n" + text, "test.pov", {}, diag);
    return r;
}

}  // namespace

TEST(PovUnsupported, ObjectsOnceLeftOutAreRead) {
    Parsed p = parse_warn(
        "isosurface { function { x*x + y*y + z*z - 1 } contained_by { box { -2, 2 } }\n"
        "  texture { pigment { rgb 1 } } translate x }\n"
        "sphere { 0, 1 }\n"
        "isosurface { function { x } }\n"
        "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> }\n"
        "julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 }\n"
        "sphere_sweep { linear_spline 2, <0, 0, 0>, 0.5, <1, 0, 0>, 0.5 }\n"
        "bicubic_patch { type 1 u_steps 4 v_steps 4 <0,0,0>,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0 }\n"
        "ovus { 1, 0.5 }\n");
    EXPECT_EQ(p.scene.objects.size(), 8u);
    EXPECT_TRUE(p.warnings.empty());
}

TEST(PovUnsupported, CsgKeepsItsOtherChildrenAndDeclarationsWork) {
    // A height_field from a pigment function is left out where the parse has no pattern hook
    // (bare importer runs like this one).
    Parsed p = parse_warn(
        "#declare Hf = height_field { function 4, 4 { pigment { rgb 1 } } }\n"
        "union { sphere { 0, 1 } object { Hf } box { 0, 1 } }\n"
        "object { Hf translate y }\n"
        "difference { height_field { function 4, 4 { pigment { rgb 1 } } } }\n"
        "sphere { 0, 1 clipped_by { height_field { function 4, 4 { pigment { rgb 1 } } } } }\n");
    ASSERT_EQ(p.scene.objects.size(), 2u);  // the union (2 children) and the clipped sphere
    auto* csg = std::get_if<glint::scene::Csg>(&p.scene.objects[0].shape);
    ASSERT_NE(csg, nullptr);
    EXPECT_EQ(csg->children.size(), 2u);
    EXPECT_TRUE(p.scene.objects[1].clipped_by.empty());
    EXPECT_EQ(p.warnings,
              (std::vector<std::string>{
                  "2:39: 'height_field from a pattern or pigment function here' is not "
                  "supported: the object is left out"}));
}

TEST(PovUnsupported, MediaPhotonsAndRadiosityAreRead) {
    Parsed p = parse_warn(
        "global_settings { photons { count 20000 gather 10, 50 media 100, 2 } }\n"
        "media { intervals 10 scattering { 1, rgb 0.1 } }\n"
        "#declare D = density { spherical color_map { [0 rgb 0] [1 rgb 1] } }\n"
        "sphere { 0, 1 hollow\n"
        "  interior { ior 1.5 media { emission 1 density { D } } }\n"
        "  photons { target 0.5 reflection on refraction off collect off pass_through }\n"
        "  radiosity { importance 0.5 }\n"
        "}\n"
        "light_source { <0, 5, 0> rgb 1 photons { refraction on area_light } }\n");
    ASSERT_EQ(p.scene.objects.size(), 1u);
    const glint::scene::Object& o = p.scene.objects[0];
    EXPECT_DOUBLE_EQ(p.scene.materials[o.material].interior.ior, 1.5);
    ASSERT_EQ(p.scene.lights.size(), 1u);
    EXPECT_EQ(p.scene.lights[0].photon_refraction, 1);
    EXPECT_EQ(p.scene.lights[0].photon_reflection, -1);
    EXPECT_TRUE(p.scene.lights[0].photon_area_light);
    // The media are read (pov_media_test covers them), and so are photons and radiosity.
    EXPECT_EQ(p.scene.media.size(), 1u);
    EXPECT_EQ(p.scene.materials[o.material].interior.media.size(), 1u);
    ASSERT_TRUE(p.scene.global.photons.has_value());
    EXPECT_EQ(p.scene.global.photons->count, 20000);
    EXPECT_EQ(p.scene.global.photons->gather_min, 10);
    EXPECT_EQ(p.scene.global.photons->gather_max, 50);
    EXPECT_EQ(p.scene.global.photons->media_steps, 100);
    EXPECT_DOUBLE_EQ(o.photon_target, 0.5);
    EXPECT_EQ(o.photon_reflection, 1);
    EXPECT_EQ(o.photon_refraction, 0);
    EXPECT_FALSE(o.photon_collect);
    EXPECT_TRUE(o.photon_pass_through);
    EXPECT_DOUBLE_EQ(o.radiosity_importance, 0.5);
    EXPECT_TRUE(p.warnings.empty());
}

TEST(PovUnsupported, CameraFeatures) {
    Parsed p = parse_warn(
        "camera { location <0, 0, -5> look_at 0 aperture 0.4 blur_samples 10 focal_point 0\n"
        "  bokeh { pigment { rgb 1 } } }\n"
        "camera { mesh_camera { 1 0 mesh { triangle { 0, x, y } } } location -z }\n");
    // (mesh_camera is rendered: render/mesh_camera.h; focal blur: render/focal_blur.h.)
    EXPECT_EQ(p.warnings,
              (std::vector<std::string>{"3:3: 'camera bokeh' is not supported: ignored"}));
    EXPECT_EQ(p.scene.camera.kind, glint::scene::CameraKind::Mesh);
}

TEST(PovUnsupported, CameraNormalIsKeptNotWarned) {
    Parsed p = parse_warn(
        "#default { normal { dents 0.3 } }\n"
        "camera { location -5*z look_at 0 normal { bumps 0.1 scale 2 } }\n");
    EXPECT_TRUE(p.warnings.empty());
    const glint::scene::Normal& n = p.scene.camera.normal;
    EXPECT_EQ(n.kind, glint::scene::PatternKind::Bumps);
    EXPECT_DOUBLE_EQ(n.amount, 0.1);
    EXPECT_DOUBLE_EQ(n.transform.inverse_point(glint::Vec3(2, 0, 0)).x, 1.0);
}

TEST(PovUnsupported, UnterminatedSkippedBlockIsAnError) {
    glint::Diagnostics diag;
    try {
        glint::pov::parse_string("camera { bokeh { pigment { rgb 1 }\n", "test.pov", {}, diag);
        ADD_FAILURE() << "no error";
    } catch (const glint::Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "expected '}' to close the bokeh opened at 1:16, got the end of the file");
    }
}

TEST(PovUnsupported, FinishFeatures) {
    Parsed p = parse_warn(
        "sphere { 0, 1 finish { diffuse albedo 0.6, 0.2 irid { 0.3 thickness 0.2 }\n"
        "  subsurface { translucency 0.5 } ior 1.5 phong 0.5 } }\n");
    ASSERT_EQ(p.scene.objects.size(), 1u);
    const auto& f = p.scene.materials[p.scene.objects[0].material].texture.finish;
    EXPECT_DOUBLE_EQ(f.diffuse, 0.6);
    EXPECT_DOUBLE_EQ(f.diffuse_back, 0.2);  // diffuse backside illumination: read, no warning
    EXPECT_DOUBLE_EQ(f.phong, 0.5);
    // (Subsurface light transport is supported: parsed, no warning.)
    EXPECT_TRUE(f.subsurface);
    EXPECT_DOUBLE_EQ(f.translucency.g, 0.5);
    EXPECT_EQ(p.warnings,
              (std::vector<std::string>{
                  "2:32: 'albedo' is not supported: ignored",
                  "3:35: finish ior is POV-Ray 3.0 syntax: write it in interior { }"}));
    // ... and the object's interior takes it, as POV-Ray 3.7's Post_Process does.
    EXPECT_DOUBLE_EQ(p.scene.materials[p.scene.objects[0].material].interior.ior, 1.5);
}

