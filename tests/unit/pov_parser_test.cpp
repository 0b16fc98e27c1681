// The POV-Ray grammar to IR: camera resolution against hand-computed vectors, each object and
// material kind, CSG material inheritance, transforms moving textures, and error places.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/unit/pov_test_util.h"

namespace glint::pov {
namespace {

using testing::error_of;
using testing::parse;

void expect_near(const Vec3& a, const Vec3& b, double tol = 1e-9) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(PovCamera, DefaultsAndLookAt) {
    auto s = parse("camera { location <0, 0, -5> look_at <0, 0, 0> }");
    expect_near(s.camera.location, {0, 0, -5});
    expect_near(s.camera.direction, {0, 0, 1});
    expect_near(s.camera.right, {1.33, 0, 0});
    expect_near(s.camera.up, {0, 1, 0});
}

TEST(PovCamera, AngleSetsDirectionFromRightWhateverTheOrder) {
    // |direction| = |right| / tan(angle/2) / 2 = (4/3) / tan(45 deg) / 2 = 2/3.
    for (const char* text :
         {"camera { location <0,0,-5> right x*4/3 angle 90 look_at 0 }",
          "camera { look_at 0 angle 90 location <0,0,-5> right x*4/3 }"}) {
        auto s = parse(text);
        expect_near(s.camera.direction, {0, 0, 2.0 / 3.0});
        expect_near(s.camera.right, {4.0 / 3.0, 0, 0});
        expect_near(s.camera.up, {0, 1, 0});
        EXPECT_EQ(s.camera.angle, 90);
    }
}

TEST(PovCamera, LookAtSideways) {
    // Looking along +x from the origin: right = sky x dir = (0,1,0)x(1,0,0) = (0,0,-1) * 1.33.
    auto s = parse("camera { location 0 look_at <10, 0, 0> }");
    expect_near(s.camera.direction, {1, 0, 0});
    expect_near(s.camera.right, {0, 0, -1.33});
    expect_near(s.camera.up, {0, 1, 0});
}

TEST(PovCamera, LeftHandedRightKeepsItsSign) {
    auto s = parse("camera { right -x look_at <0, 0, 1> }");
    expect_near(s.camera.right, {-1, 0, 0});
}

TEST(PovCamera, OrthographicSizedByLookAtDistance) {
    // No up/right given: both scaled by |look_at - location| / |direction| = 10.
    auto s = parse("camera { orthographic location <0, 0, -10> look_at 0 }");
    EXPECT_EQ(s.camera.kind, scene::CameraKind::Orthographic);
    expect_near(s.camera.right, {13.3, 0, 0});
    expect_near(s.camera.up, {0, 10, 0});
    // With up and right given they are kept.
    s = parse("camera { orthographic location <0,0,-10> right 8*x up 6*y look_at 0 }");
    expect_near(s.camera.right, {8, 0, 0});
    expect_near(s.camera.up, {0, 6, 0});
}

TEST(PovCamera, TransformsApplyLast) {
    auto s = parse("camera { location <0, 0, -5> look_at 0 translate <1, 2, 3> }");
    expect_near(s.camera.location, {1, 2, -2});
    expect_near(s.camera.direction, {0, 0, 1});
}

TEST(PovCamera, NonLinearProjections) {
    auto s = parse("camera { fisheye angle 180 location <0, 0, -5> look_at 0 }");
    EXPECT_EQ(s.camera.kind, scene::CameraKind::Fisheye);
    EXPECT_DOUBLE_EQ(s.camera.angle, 180);  // used as given, not folded into direction
    s = parse("camera { cylinder 3 location <0, 0, -5> }");
    EXPECT_EQ(s.camera.kind, scene::CameraKind::Cylinder3);
    EXPECT_DOUBLE_EQ(s.camera.angle, 90);  // POV-Ray's default
    s = parse("camera { spherical angle 120 location 0 }");
    EXPECT_DOUBLE_EQ(s.camera.h_angle, 120);
    EXPECT_DOUBLE_EQ(s.camera.v_angle, 60);  // half of H unless given
    EXPECT_EQ(error_of("camera {\n  cylinder 5 }"),
              "2:3: invalid cylinder camera type 5; valid types are 1 to 4");
}

TEST(PovCamera, BadCamerasFail) {
    EXPECT_EQ(error_of("camera { location 0 look_at 0 }"),
              "1:8: the camera location and look_at point must be different");
}

template <typename T>
const T& shape(const scene::Scene& s, size_t i) {
    return std::get<T>(s.objects.at(i).shape);
}

TEST(PovObjects, Shapes) {
    auto s = parse(
        "sphere { <1,2,3>, 4 }\n"
        "plane { <0, 2, 0>, 3 }\n"
        "box { <-1,-2,-3>, <1,2,3> }\n"
        "cylinder { 0, y*2, 0.5 open }\n"
        "cone { 0, 1, y, 0.25 }\n"
        "disc { 0, <0, 0, 2>, 2, 1 }\n"
        "torus { 2, 0.5 sturm }\n"
        "triangle { 0, x, y }\n"
        "smooth_triangle { 0, z, x, z, y, z }\n");
    ASSERT_EQ(s.objects.size(), 9u);
    EXPECT_EQ(shape<scene::Sphere>(s, 0).center, Vec3(1, 2, 3));
    EXPECT_EQ(shape<scene::Sphere>(s, 0).radius, 4);
    EXPECT_EQ(shape<scene::Plane>(s, 1).normal, Vec3(0, 1, 0));  // normalized
    EXPECT_EQ(shape<scene::Plane>(s, 1).distance, 3);            // distance as written
    EXPECT_EQ(shape<scene::Box>(s, 2).corner2, Vec3(1, 2, 3));
    EXPECT_TRUE(shape<scene::Cylinder>(s, 3).open);
    EXPECT_EQ(shape<scene::Cylinder>(s, 3).cap, Vec3(0, 2, 0));
    EXPECT_EQ(shape<scene::Cone>(s, 4).cap_radius, 0.25);
    EXPECT_FALSE(shape<scene::Cone>(s, 4).open);
    EXPECT_EQ(shape<scene::Disc>(s, 5).normal, Vec3(0, 0, 1));
    EXPECT_EQ(shape<scene::Disc>(s, 5).hole_radius, 1);
    EXPECT_TRUE(shape<scene::Torus>(s, 6).sturm);
    EXPECT_EQ(shape<scene::Triangle>(s, 7).p[1], Vec3(1, 0, 0));
    EXPECT_EQ(shape<scene::SmoothTriangle>(s, 8).n[2], Vec3(0, 0, 1));
    for (const auto& o : s.objects) EXPECT_GE(o.material, 0);
}

TEST(PovObjects, CommasBetweenVectorsAreOptional) {
    auto s = parse("box { <-1, -2, -3> <1, 2, 3> }\ncylinder { <0 0 0> <0 2 0> 0.5 }");
    EXPECT_EQ(shape<scene::Box>(s, 0).corner1, Vec3(-1, -2, -3));
    EXPECT_EQ(shape<scene::Box>(s, 0).corner2, Vec3(1, 2, 3));
    EXPECT_EQ(shape<scene::Cylinder>(s, 1).radius, 0.5);
}

TEST(PovObjects, MeshAndMesh2) {
    auto s = parse(
        "#declare M = mesh { triangle { 0, x, y } smooth_triangle { 0, z, x, z, y, z }"
        " inside_vector z }\n"
        "object { M translate x }\nobject { M }\n"
        "mesh2 { vertex_vectors { 4, 0, x, y, z } normal_vectors { 1, z }"
        " face_indices { 2, <0,1,2>, <1,2,3> } normal_indices { 2, <0,0,0>, <0,0,0> } }\n");
    ASSERT_EQ(s.meshes.size(), 2u);
    EXPECT_EQ(s.meshes[0].faces.size(), 2u);
    EXPECT_TRUE(s.meshes[0].has_inside_vector);
    EXPECT_EQ(s.meshes[0].faces[1].n[0], 0);
    EXPECT_EQ(shape<scene::MeshRef>(s, 0).mesh, 0);
    EXPECT_EQ(shape<scene::MeshRef>(s, 1).mesh, 0);  // a declared mesh is shared
    EXPECT_EQ(s.meshes[1].positions.size(), 4u);
    EXPECT_EQ(s.meshes[1].faces[1].v, (std::array<int, 3>{1, 2, 3}));
    EXPECT_EQ(s.meshes[1].faces[1].n, (std::array<int, 3>{0, 0, 0}));
    EXPECT_EQ(error_of("mesh2 { vertex_vectors { 1, 0 } face_indices { 1, <0, 1, 0> } }"),
              "1:51: vertex index 1 is out of range (0..0)");
}

TEST(PovObjects, CsgMaterialsAndLights) {
    auto s = parse(
        "union {\n"
        "  sphere { 0, 1 pigment { rgb x } }\n"
        "  sphere { x, 1 }\n"
        "  light_source { <0, 5, 0> rgb 1 }\n"
        "  translate <10, 0, 0>\n"
        "}\n");
    ASSERT_EQ(s.objects.size(), 1u);
    const auto& csg = std::get<scene::Csg>(s.objects[0].shape);
    ASSERT_EQ(csg.children.size(), 2u);
    EXPECT_GE(s.objects[0].material, 0);
    EXPECT_GE(csg.children[0].material, 0);
    EXPECT_EQ(csg.children[1].material, -1);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].location, Vec3(10, 5, 0));
    // The child's pigment moved with the union.
    const auto& pig = s.materials[csg.children[0].material].texture.pigment;
    EXPECT_EQ(pig.transform.point(Vec3(0, 0, 0)), Vec3(10, 0, 0));
}

TEST(PovObjects, DeclaredObjectNameAloneIsACopy) {
    // POV-Ray's Parse_Object takes an object identifier as a shape keyword: a statement of
    // its own, and a CSG child, both without modifiers. (First in a CSG it is Parse_CSG's
    // `union { B mods }`, a copy of B: hence the sphere first.)
    auto s = parse(
        "#declare B = sphere { 0, 1 pigment { rgb x } translate y }\n"
        "B\n"
        "union { sphere { 0, 0.5 } B object { B translate x } }\n");
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_TRUE(std::holds_alternative<scene::Sphere>(s.objects[0].shape));
    EXPECT_EQ(s.objects[0].transform.point(Vec3(0, 0, 0)), Vec3(0, 1, 0));
    const auto& csg = std::get<scene::Csg>(s.objects[1].shape);
    ASSERT_EQ(csg.children.size(), 3u);
    EXPECT_EQ(csg.children[1].transform.point(Vec3(0, 0, 0)), Vec3(0, 1, 0));
    EXPECT_EQ(csg.children[2].transform.point(Vec3(0, 0, 0)), Vec3(1, 1, 0));
}

TEST(PovObjects, Version1TextureItemsStraightInATexture) {
    // Under #version below 3.0 POV-Ray reads a texture in its 1.0 syntax: pigment, normal and
    // finish items written straight in it (Parse_Vers1_Texture), with one warning.
    const std::string body =
        "sphere { 0, 1 texture { gradient x colour_map { [0 rgb 0][1 rgb 1] } turbulence 0.2\n"
        "  bumps 0.4 phong 0.5 ior 1.5 reflection 0.25 } }\n";
    std::vector<std::string> warnings;
    Diagnostics diag([&](const Diagnostic& d) { warnings.push_back(d.message); });
    const scene::Scene sc = pov::parse_string("#version 2.0;\n" + body, "test.pov", {}, diag);
    ASSERT_EQ(sc.objects.size(), 1u);
    const scene::Material& m = sc.materials[sc.objects[0].material];
    EXPECT_EQ(m.texture.pigment.kind, scene::PatternKind::Gradient);
    EXPECT_EQ(m.texture.pigment.color_map.size(), 2u);
    EXPECT_EQ(m.texture.normal.kind, scene::PatternKind::Bumps);
    EXPECT_DOUBLE_EQ(m.texture.normal.amount, 0.4);
    EXPECT_DOUBLE_EQ(m.texture.finish.phong, 0.5);
    EXPECT_DOUBLE_EQ(m.interior.ior, 1.5);
    ASSERT_GE(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("POV-Ray 1.0 syntax"), std::string::npos) << warnings[0];
    // A 3.x scene still may not.
    EXPECT_EQ(error_of("#version 3.7;\n" + body),
              "2:36: 'colour_map' cannot be used directly in a texture");
}

TEST(PovObjects, TransformsBeforeTextureDoNotMoveIt) {
    auto s = parse("sphere { 0, 1 translate x pigment { checker scale 2 } translate y }");
    const auto& pig = s.materials[s.objects[0].material].texture.pigment;
    EXPECT_EQ(pig.kind, scene::PatternKind::Checker);
    EXPECT_EQ(pig.transform.point(Vec3(1, 1, 1)), Vec3(2, 3, 2));
    EXPECT_EQ(s.objects[0].transform.point(Vec3(0, 0, 0)), Vec3(1, 1, 0));
    // Default checker colors: blue and green.
    EXPECT_EQ(pig.entries.at(0).color.rgb, Color(0, 0, 1));
    EXPECT_EQ(pig.entries.at(1).color.rgb, Color(0, 1, 0));
}

TEST(PovObjects, ModifiersAndFlags) {
    auto s = parse(
        "#declare B = box { -1, 1 }\n"
        "object { B inverse hollow no_shadow no_image no_reflection double_illuminate"
        " bounded_by { sphere { 0, 2 } } clipped_by { bounded_by } }\n"
        "sphere { 0, 1 hollow off }");
    const auto& o = s.objects[0];
    EXPECT_TRUE(o.inverse && o.hollow && o.no_shadow && o.no_image && o.no_reflection &&
                o.double_illuminate);
    EXPECT_EQ(o.name, "B");
    ASSERT_EQ(o.bounded_by.size(), 1u);
    ASSERT_EQ(o.clipped_by.size(), 1u);
    EXPECT_FALSE(s.objects[1].hollow);
}

TEST(PovObjects, CsgFlagsReachChildren) {
    auto s = parse("union { union { sphere { 0, 1 } } sphere { x, 1 } no_shadow no_image }");
    const auto& top = std::get<scene::Csg>(s.objects[0].shape);
    const auto& inner = std::get<scene::Csg>(top.children[0].shape);
    EXPECT_TRUE(inner.children[0].no_shadow);
    EXPECT_TRUE(inner.children[0].no_image);
    EXPECT_FALSE(inner.children[0].no_reflection);
    EXPECT_TRUE(top.children[1].no_shadow);
}

TEST(PovLights, AllKinds) {
    auto s = parse(
        "light_source { <1,2,3> color rgb <1,0.5,0.25> spotlight point_at <0,0,0> radius 10"
        " falloff 20 tightness 5 fade_distance 4 fade_power 2 shadowless }\n"
        "light_source { 0, 1 parallel point_at -y }\n"
        "light_source { 0, 1 area_light x*2, z*2, 3, 4 adaptive 1 jitter circular orient }\n");
    ASSERT_EQ(s.lights.size(), 3u);
    EXPECT_EQ(s.lights[0].kind, scene::LightKind::Spot);
    EXPECT_EQ(s.lights[0].color, Color(1, 0.5, 0.25));
    EXPECT_EQ(s.lights[0].falloff, 20);
    EXPECT_TRUE(s.lights[0].shadowless);
    EXPECT_EQ(s.lights[0].fade_power, 2);
    EXPECT_TRUE(s.lights[1].parallel);
    EXPECT_EQ(s.lights[1].point_at, Vec3(0, -1, 0));
    ASSERT_TRUE(s.lights[2].area.has_value());
    EXPECT_EQ(s.lights[2].area->size2, 4);
    EXPECT_TRUE(s.lights[2].area->jitter && s.lights[2].area->circular && s.lights[2].area->orient);
}

TEST(PovMaterials, FinishInteriorAndMaps) {
    auto s = parse(
        "#declare F = finish { ambient 0.2 diffuse 0.7 phong 0.5 phong_size 60 specular 0.3"
        " roughness 0.01 brilliance 2 metallic reflection { 0.1, 0.8 falloff 2 fresnel on"
        " metallic 0.5 } }\n"
        "sphere { 0, 1 texture { pigment { gradient <0, 2, 0> color_map { [0 rgb 0] [1 rgb 1] } }"
        " finish { F } } interior { ior 1.5 fade_distance 2 fade_power 1001 fade_color rgb x } }\n"
        "sphere { 0, 1 finish { reflection rgb <0.1, 0.2, 0.3> } }\n");
    const auto& m = s.materials[s.objects[0].material];
    const auto& f = m.texture.finish;
    EXPECT_EQ(f.ambient, Color(0.2, 0.2, 0.2));
    EXPECT_EQ(f.diffuse, 0.7);
    EXPECT_EQ(f.phong_size, 60);
    EXPECT_EQ(f.roughness, 0.01);
    EXPECT_EQ(f.metallic, 1);
    EXPECT_EQ(f.reflection.min, Color(0.1, 0.1, 0.1));
    EXPECT_EQ(f.reflection.max, Color(0.8, 0.8, 0.8));
    EXPECT_EQ(f.reflection.falloff, 2);
    EXPECT_TRUE(f.reflection.fresnel);
    EXPECT_EQ(f.reflection.metallic, 0.5);
    EXPECT_EQ(m.texture.pigment.kind, scene::PatternKind::Gradient);
    EXPECT_EQ(m.texture.pigment.params.vector, Vec3(0, 1, 0));
    ASSERT_EQ(m.texture.pigment.color_map.size(), 2u);
    EXPECT_EQ(m.texture.pigment.color_map[1].color.rgb, Color(1, 1, 1));
    EXPECT_EQ(m.interior.ior, 1.5);
    EXPECT_EQ(m.interior.fade_power, 1001);
    EXPECT_EQ(m.interior.fade_color, Color(1, 0, 0));
    const auto& r = s.materials[s.objects[1].material].texture.finish.reflection;
    EXPECT_EQ(r.min, Color(0.1, 0.2, 0.3));
    EXPECT_EQ(r.max, Color(0.1, 0.2, 0.3));
}

// POV-Ray's CSG children share their parent's interior unless they declare one
// (Post_Process copies the pointer): a child with only a texture of its own keeps the
// parent's interior id, a child with an interior gets a new one, and each top-level object
// starts its own.
TEST(PovMaterials, InteriorIdsFollowTheDeclarations) {
    auto s = parse(
        "difference {\n"
        "  box { -1, 1 texture { pigment { rgbf 1 } } interior { ior 1.5 } }\n"
        "  sphere { 0, 0.5 texture { pigment { rgbt 0.6 } } }\n"
        "  sphere { 0, 0.2 texture { pigment { rgbt 0.5 } } interior { ior 1.5 } }\n"
        "}\n"
        "sphere { 0, 1 }\n");
    const auto& cut = std::get<scene::Csg>(s.objects[0].shape);
    auto id = [&](int material) { return s.materials[static_cast<size_t>(material)].interior_id; };
    const int whole = id(s.objects[0].material);
    EXPECT_NE(id(cut.children[0].material), whole);
    EXPECT_EQ(id(cut.children[1].material), whole);  // the difference's (default) interior
    EXPECT_EQ(s.materials[static_cast<size_t>(cut.children[1].material)].interior.ior, 1.0);
    EXPECT_NE(id(cut.children[2].material), whole);
    EXPECT_NE(id(cut.children[2].material), id(cut.children[0].material));
    EXPECT_NE(id(s.objects[1].material), whole);
}

TEST(PovMaterials, SecondTextureIsALayerOverTheFirst) {
    auto s = parse("#declare S = sphere { 0, 1 texture { pigment { rgb x } } }\n"
                   "object { S texture { pigment { rgbt <0, 1, 0, 0.5> } } }");
    const auto& t = s.materials[s.objects[0].material].texture;
    EXPECT_EQ(t.pigment.color.rgb, Color(1, 0, 0));
    ASSERT_EQ(t.layers.size(), 1u);
    EXPECT_EQ(t.layers[0].pigment.color.rgb, Color(0, 1, 0));
}

TEST(PovMaterials, ColorMapEntryForms) {
    auto s = parse(
        "sphere { 0, 1 pigment { gradient x color_map { [0, rgb 0.5] [0.5 color rgb 1]"
        " [0.6, 0.9 color rgb x color rgb y] } } }\n"
        "default { finish { ambient 0.4 } }\nsphere { 0, 1 }");
    const auto& map = s.materials[s.objects[0].material].texture.pigment.color_map;
    ASSERT_EQ(map.size(), 4u);
    EXPECT_EQ(map[0].color.rgb, Color(0.5, 0.5, 0.5));
    EXPECT_EQ(map[2].value, 0.6);
    EXPECT_EQ(map[3].value, 0.9);
    EXPECT_EQ(map[3].color.rgb, Color(0, 1, 0));
    EXPECT_EQ(s.materials[s.objects[1].material].texture.finish.ambient, Color(0.4, 0.4, 0.4));
}

TEST(PovMaterials, ImageMapMissingFile) {
    try {
        parse("sphere { 0, 1 pigment { image_map { png\n   \"no_such.png\" } } }");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::MissingFile);
        EXPECT_EQ(e.loc().line, 2);
        EXPECT_EQ(e.loc().column, 4);
    }
}

// The messages glint gives for what it lacks, at the keyword: "'X' is not supported: ...".
std::vector<std::string> warnings_of(const std::string& text) {
    Diagnostics diag;
    parse_string(text, "test.pov", {}, diag);
    std::vector<std::string> out;
    for (const Diagnostic& d : diag.all())
        if (d.message.find("is not supported") != std::string::npos)
            out.push_back(std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + ": " +
                          d.message);
    return out;
}

TEST(PovMaterials, UnsupportedFeaturesSaySo) {
    // A pattern glint lacks: its arguments are read over, the normal stays smooth.
    EXPECT_EQ(warnings_of("sphere { 0, 1 normal { pavement 0.5 } }"),
              std::vector<std::string>{
                  "1:24: 'pavement' is not supported: the normal is not perturbed by it"});
    EXPECT_EQ(warnings_of("sphere { 0, 1 pigment { pavement number_of_sides 4 "
                          "color_map { [0 rgb 1] [1 rgb 0] } } }"),
              std::vector<std::string>{"1:25: 'pavement' is not supported: the pattern is "
                                       "constant 0 (its map's first entry)"});
    EXPECT_TRUE(warnings_of("sphere { 0, 1 pigment { aoi color_map { [0 rgb 1] [1 rgb 0] } } }")
                    .empty());
    // slope as POV-Ray 3.7 prepares it: unit vectors, hi - lo, weights by length.
    auto sl = parse("sphere { 0, 1 texture { slope { -y*3, 0, 0.5 altitude y, 0.005, 0.4 }"
                    " texture_map { [0 pigment { rgb 0 }] [1 pigment { rgb 1 }] } } }");
    const scene::SlopeParams& sp = sl.materials.back().texture.params.slope;
    EXPECT_EQ(sl.materials.back().texture.kind, scene::PatternKind::Slope);
    EXPECT_EQ(sp.vector, Vec3(0, -1, 0));
    EXPECT_EQ(sp.base, -2);
    EXPECT_DOUBLE_EQ(sp.span, 0.5);
    EXPECT_EQ(sp.altitude_base, 2);
    EXPECT_DOUBLE_EQ(sp.altitude_lo, 0.005);
    EXPECT_DOUBLE_EQ(sp.altitude_span, 0.4 - 0.005);
    EXPECT_DOUBLE_EQ(sp.weight, 0.75);
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { slope { point_at 0 altitude y } } }"),
              "1:44: 'altitude' cannot be used with 'point_at' in the slope pattern");
    // irid { amount thickness t turbulence <u> } (POV-Ray reads a vector, keeps its x).
    Diagnostics diag;
    scene::Scene s = parse_string(
        "sphere { 0, 1 finish { irid { 0.3 turbulence <0.4, 9, 9> thickness 0.2 } phong 1 } }",
        "test.pov", {}, diag);
    const scene::Finish& fi = s.materials.back().texture.finish;
    for (const Diagnostic& d : diag.all()) EXPECT_EQ(d.message.find("irid"), std::string::npos);
    EXPECT_DOUBLE_EQ(fi.irid, 0.3);
    EXPECT_DOUBLE_EQ(fi.irid_turbulence, 0.4);
    EXPECT_DOUBLE_EQ(fi.irid_thickness, 0.2);
    EXPECT_DOUBLE_EQ(fi.phong, 1.0);
    // An ovus needs its two radii (shapes_ovus_test.cpp).
    EXPECT_NE(error_of("ovus { }"), "(no error)");
    // tiles is a checker texture (pov_patterns_test.cpp): no warning.
    EXPECT_EQ(warnings_of("sphere { 0, 1 texture { tiles { texture { } tile2 texture { } } } }"),
              std::vector<std::string>{});
}

TEST(PovScene, BackgroundTransmitAsPovRayWritesItWithoutAlpha) {
    // POV-Ray 3.7 composes a 3.7 scene's background over black; an older scene's keeps its
    // colour (measured: rgb <0,0,1> transmit 0.5 writes 0.5 and 1 in the blue channel).
    for (const auto& [version, blue] : {std::pair{"3.7", 0.5}, std::pair{"3.6", 1.0}}) {
        auto s = parse(std::string("#version ") + version +
                       ";\nbackground { rgb <0, 0, 1> transmit 0.5 }\n");
        EXPECT_DOUBLE_EQ(s.background.rgb.b, blue) << version;
        EXPECT_EQ(s.background.transmit, 0.0);
        EXPECT_EQ(s.background.filter, 0.0);
    }
}

TEST(PovScene, GlobalSettingsBackgroundSky) {
    Diagnostics diag;
    auto s = parse_string(
        "#version 3.7;\n"
        "global_settings { assumed_gamma 1.0 max_trace_level 10 adc_bailout 0.01"
        " ambient_light rgb <0.5, 0.5, 0.5> radiosity { count 10 } }\n"
        "background { color rgb <0.1, 0.2, 0.3> }\n"
        "sky_sphere { pigment { rgb 1 } pigment { rgbt <0, 0, 0, 0.5> } rotate 90*y }\n",
        "t.pov", {}, diag);
    EXPECT_EQ(*s.global.assumed_gamma, 1.0);
    EXPECT_EQ(s.global.max_trace_level, 10);
    EXPECT_EQ(s.global.ambient_light, Color(0.5, 0.5, 0.5));
    EXPECT_EQ(s.background.rgb, Color(0.1, 0.2, 0.3));
    ASSERT_TRUE(s.sky_sphere.has_value());
    EXPECT_EQ(s.sky_sphere->pigments.size(), 2u);
    ASSERT_TRUE(s.global.radiosity.has_value());
    EXPECT_EQ(s.global.radiosity->count, 10);
    EXPECT_EQ(diag.warning_count(), 0);
}

TEST(PovScene, GlobalRadiositySettings) {
    Diagnostics diag;
    auto s = parse_string(
        "#version 3.7;\n"
        "global_settings { radiosity { pretrace_start 0.16 pretrace_end 0.02 count 80, 2000\n"
        "  nearest_count 8, 3 error_bound 0.5 recursion_limit 3 low_error_factor 0.7\n"
        "  gray_threshold 0.2 minimum_reuse 0.01 maximum_reuse 0.1 brightness 1.3\n"
        "  adc_bailout 0.005 normal on media on always_sample off max_sample 2 } }\n"
        "#default { radiosity { importance 0.25 } }\n"
        "sphere { 0, 1 no_radiosity } sphere { 0, 1 radiosity { importance 0.5 } }\n",
        "t.pov", {}, diag);
    ASSERT_TRUE(s.global.radiosity.has_value());
    const scene::Radiosity& r = *s.global.radiosity;
    EXPECT_EQ(r.pretrace_start, 0.16);
    EXPECT_EQ(r.pretrace_end, 0.02);
    EXPECT_EQ(r.count, 80);
    EXPECT_EQ(r.direction_pool, 2000);
    EXPECT_EQ(r.nearest_count, 8);
    EXPECT_EQ(r.nearest_count_pretrace, 3);
    EXPECT_EQ(r.error_bound, 0.5);
    EXPECT_EQ(r.recursion_limit, 3);
    EXPECT_EQ(r.low_error_factor, 0.7);
    EXPECT_EQ(r.gray_threshold, 0.2);
    EXPECT_EQ(r.minimum_reuse, 0.01);
    EXPECT_EQ(r.maximum_reuse, 0.1);
    EXPECT_EQ(r.brightness, 1.3);
    EXPECT_EQ(r.adc_bailout, 0.005);
    EXPECT_TRUE(r.normal);
    EXPECT_TRUE(r.media);
    EXPECT_FALSE(r.always_sample);
    EXPECT_EQ(r.max_sample, 2);
    EXPECT_EQ(s.global.radiosity_importance, 0.25);
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_TRUE(s.objects[0].no_radiosity);
    EXPECT_EQ(s.objects[0].radiosity_importance, -1);
    EXPECT_EQ(s.objects[1].radiosity_importance, 0.5);
    EXPECT_EQ(diag.warning_count(), 0);
    // An empty block is POV-Ray's defaults; minimum_reuse follows a small maximum_reuse down.
    auto d = parse_string("global_settings { radiosity { maximum_reuse 0.02 } }", "t.pov", {},
                          diag);
    EXPECT_EQ(d.global.radiosity->count, 35);
    EXPECT_EQ(d.global.radiosity->error_bound, 1.8);
    EXPECT_EQ(d.global.radiosity->minimum_reuse, 0.01);
    // POV-Ray's range checks.
    for (const char* bad : {"global_settings { radiosity { count 0 } }",
                            // the fuzzer's: a count past int (and any pool past glint's limit)
                            "global_settings { radiosity { count 20000002000000 } }",
                            "global_settings { radiosity { count 10, 1e30 } }",
                            "global_settings { radiosity { count 10, -1e30 } }",
                            "global_settings { radiosity { pretrace_start 0.01 pretrace_end 0.1 } }",
                            "global_settings { radiosity { nearest_count 21 } }",
                            "global_settings { radiosity { recursion_limit 0 } }",
                            "global_settings { radiosity { error_bound -1 } }",
                            "sphere { 0, 1 radiosity { importance 0 } }"})
        EXPECT_THROW(parse_string(bad, "t.pov", {}, diag), Error) << bad;
}

TEST(PovScene, GlobalSubsurfaceSettings) {
    Diagnostics diag;
    auto s = parse_string(
        "#version 3.7;\n"
        "global_settings { mm_per_unit 40 subsurface { samples 400, 40 radiosity off } }\n",
        "t.pov", {}, diag);
    EXPECT_EQ(s.global.mm_per_unit, 40);
    EXPECT_TRUE(s.global.subsurface);
    EXPECT_EQ(s.global.subsurface_samples_diffuse, 400);
    EXPECT_EQ(s.global.subsurface_samples_single, 40);
    EXPECT_EQ(diag.warning_count(), 0);
    // Without the block: off, POV-Ray's defaults.
    auto d = parse_string("#version 3.7; global_settings { }\n", "t.pov", {}, diag);
    EXPECT_FALSE(d.global.subsurface);
    EXPECT_EQ(d.global.mm_per_unit, 10);
    EXPECT_EQ(d.global.subsurface_samples_diffuse, 50);
}

TEST(PovScene, VersionTracking) {
    // No #version at all: POV-Ray 3.7 takes the scene as 3.62 (EffectiveLanguageVersion).
    Diagnostics diag;
    auto s = parse_string("sphere { 0, version }", "t.pov", {}, diag);
    EXPECT_EQ(s.version, 3.62);
    EXPECT_EQ(std::get<scene::Sphere>(s.objects[0].shape).radius, 3.7);
    EXPECT_EQ(diag.warning_count(), 1);
    EXPECT_EQ(parse("#version 3.5;\n#declare V = version;\n#version 3.7;\n#version V;").version,
              3.5);
}

TEST(PovErrors, PlacesAndWording) {
    EXPECT_EQ(error_of("sphere { 0, 1\n"),
              "2:1: expected '}' to close the sphere opened at 1:8, got the end of the file");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { rgb 1 }\nfoo }"),
              "2:1: expected an object modifier or '}' to close the sphere opened at 1:8, got 'foo'");
    EXPECT_EQ(error_of("spere { 0, 1 }"), "1:1: unknown keyword or identifier 'spere'");
    EXPECT_EQ(error_of("sphere { <1, 2, 1 pigment { rgb 1 } }"),
              "1:19: expected ',' or '>' in the vector, got 'pigment'");
    EXPECT_EQ(error_of("#declare P = pigment { rgb 1 }\nP"),
              "2:1: expected an object, light_source, camera or directive, got a pigment 'P'");
    EXPECT_EQ(error_of("sphere { 0, 1 texture { T } }"),
              "1:25: expected a texture item (pigment, normal, finish, pattern, transform), "
              "got the unknown identifier 'T'");
    EXPECT_EQ(error_of("#declare C = rgb 1;\nobject { C }"),
              "2:10: expected an object identifier, got a color 'C'");
}

// finish, normal, interior and texture bodies share one rule: an identifier of the body's own
// type may only be the first item, and an identifier of another type is named in the error.
TEST(PovErrors, BodyIdentifierMustComeFirstAndHaveTheRightType) {
    const std::string decls =
        "#declare F = finish { ambient 0.3 }\n#declare I = interior { ior 1.5 }\n"
        "#declare T = texture { finish { F } }\n#declare C = rgb 1;\n";
    EXPECT_EQ(error_of(decls + "sphere { 0, 1 finish { diffuse 0.5 F } }"),
              "5:36: a finish identifier must come first in the finish");
    EXPECT_EQ(error_of(decls + "sphere { 0, 1 finish { C } }"),
              "5:24: expected a finish, got a color 'C'");
    EXPECT_EQ(error_of(decls + "sphere { 0, 1 interior { ior 1.2 I } }"),
              "5:34: an interior identifier must come first in the interior");
    EXPECT_EQ(error_of(decls + "sphere { 0, 1 interior { F } }"),
              "5:26: expected an interior, got a finish 'F'");
    EXPECT_EQ(error_of(decls + "sphere { 0, 1 texture { finish { F } T } }"),
              "5:38: a texture identifier must come first in the texture");
    EXPECT_EQ(error_of(decls + "sphere { 0, 1 texture { I } }"),
              "5:25: expected a texture, got an interior 'I'");
    EXPECT_EQ(error_of(decls + "#declare N = normal { scale 2 }\n"
                               "sphere { 0, 1 normal { scale 1 N } }"),
              "6:32: a normal identifier must come first in the normal");
    EXPECT_EQ(error_of(decls + "sphere { 0, 1 normal { F } }"),
              "5:24: expected a normal, got a finish 'F'");
    // First is fine: the identifier is copied, later items change the copy.
    auto s = parse(decls + "sphere { 0, 1 finish { F diffuse 0.5 } interior { I fade_power 2 } }");
    const auto& m = s.materials[s.objects[0].material];
    EXPECT_EQ(m.texture.finish.ambient, Color(0.3, 0.3, 0.3));
    EXPECT_EQ(m.texture.finish.diffuse, 0.5);
    EXPECT_EQ(m.interior.ior, 1.5);
    EXPECT_EQ(m.interior.fade_power, 2);
}

}  // namespace
}  // namespace glint::pov
