// OBJ/MTL import (formats/obj): structure, the MTL -> material mapping of MTL.md, and broken
// input reported with file:line:col.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "formats/obj/obj_importer.h"
#include "formats/pov/parser.h"

namespace glint::obj {
namespace {

namespace fs = std::filesystem;

class ObjImporter : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("glint-obj-test-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string write(const std::string& name, const std::string& text) {
        std::ofstream(dir_ / name) << text;
        return (dir_ / name).string();
    }
    fs::path dir_;
};

const char* kTwoObjects = R"(mtllib m.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vn 0 0 1
vt 0 0
vt 1 0
vt 1 1
vt 0 1
o Quad
usemtl shiny
f 1/1/1 2/2/1 3/3/1 4/4/1
o Tri
usemtl missing_material
v 5 5 5
f 2 3 5
)";

const char* kMtl = R"(newmtl shiny
Kd 0.5 0.25 1
Ks 0.5 0.5 0.5
Ns 250
Ni 1.5
d 0.75
Pm 0.3
map_Kd -o 0.5 0.25 0 -s 2 2 1 absent.png
)";

TEST_F(ObjImporter, ObjectsMeshesAndMaterials) {
    write("m.mtl", kMtl);
    std::string obj = write("a.obj", kTwoObjects);
    scene::Scene s;
    Diagnostics diag;
    ObjImport im = import_obj(obj, s, Transform{}, -1, diag);
    ASSERT_EQ(im.object_count, 2);
    EXPECT_EQ(im.triangles, 3);  // the quad becomes two triangles
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(s.objects[0].name, "Quad");
    EXPECT_EQ(s.objects[1].name, "Tri");
    const scene::Mesh& quad = s.meshes[std::get<scene::MeshRef>(s.objects[0].shape).mesh];
    EXPECT_EQ(quad.positions.size(), 4u);  // only the vertices the object uses
    EXPECT_EQ(quad.normals.size(), 1u);
    EXPECT_EQ(quad.uvs.size(), 4u);
    EXPECT_GE(quad.faces[0].n[0], 0);  // smooth: normals given
    const scene::Mesh& tri = s.meshes[std::get<scene::MeshRef>(s.objects[1].shape).mesh];
    EXPECT_EQ(tri.positions.size(), 3u);
    // Each mesh carries its object's name and the line of the statement that named it, for
    // what is said about its faces.
    EXPECT_EQ(quad.name, "Quad");
    EXPECT_EQ(quad.loc.line, 11);
    EXPECT_EQ(tri.name, "Tri");
    EXPECT_EQ(tri.loc.line, 14);
    EXPECT_EQ(tri.faces[0].n[0], -1);  // flat: no normals
    EXPECT_EQ(tri.faces[0].uv[0], -1);
    // The MTL's material, and a default one for the unknown `usemtl`.
    const scene::Material& shiny = s.materials[quad.faces[0].material];
    EXPECT_FALSE(shiny.pbr.derived);
    EXPECT_DOUBLE_EQ(shiny.pbr.base_color.b, 1.0);
    EXPECT_NEAR(shiny.pbr.roughness, 0.5, 1e-12);  // 1 - sqrt(250 / 1000)
    EXPECT_NEAR(shiny.pbr.metallic, 0.3, 1e-6);
    EXPECT_NEAR(shiny.pbr.alpha, 0.75, 1e-6);
    EXPECT_NEAR(shiny.pbr.ior, 1.5, 1e-6);
    EXPECT_NEAR(shiny.texture.pigment.color.transmit, 0.25, 1e-6);
    EXPECT_EQ(shiny.pbr.base_color_map.file, "absent.png");
    EXPECT_FALSE(shiny.pbr.base_color_map.present());
    EXPECT_NEAR(shiny.pbr.base_color_map.offset.x, 0.5, 1e-6);
    EXPECT_NEAR(shiny.pbr.base_color_map.scale.y, 2.0, 1e-6);
    const scene::Material& fallback = s.materials[tri.faces[0].material];
    EXPECT_NEAR(fallback.pbr.base_color.r, 0.8, 1e-12);
    // The missing texture is a warning that names it; the material still exists.
    bool warned = false;
    for (const auto& d : diag.all())
        warned |= d.message.find("texture 'absent.png' not found") != std::string::npos;
    EXPECT_TRUE(warned);
}

TEST_F(ObjImporter, OverrideAndTransform) {
    write("m.mtl", kMtl);
    std::string obj = write("a.obj", kTwoObjects);
    scene::Scene s;
    s.materials.resize(1);
    Diagnostics diag;
    ObjImport im = import_obj(obj, s, Transform::translate(Vec3(10, 0, 0)), 0, diag);
    for (const auto& m : s.meshes)
        for (const auto& f : m.faces) EXPECT_EQ(f.material, 0);
    EXPECT_DOUBLE_EQ(im.bounds.lo.x, 10.0);
    EXPECT_DOUBLE_EQ(im.bounds.hi.x, 15.0);
}

TEST_F(ObjImporter, OutOfRangeIndexNamesItsLineAndColumn) {
    std::string obj = write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 7\n");
    scene::Scene s;
    Diagnostics diag;
    try {
        import_obj(obj, s, Transform{}, -1, diag);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Scene);
        EXPECT_EQ(e.loc().line, 5);
        EXPECT_EQ(e.loc().column, 7);
        EXPECT_STREQ(e.what(), "vertex index 7 is out of range (3 defined so far)");
    }
}

TEST_F(ObjImporter, NormalsNamedButNeverDefinedWarnAndShadeFlat) {
    // Some exporters write `f v/vt/vn` with no `vn` statement at all: a warning, not an error.
    std::string obj = write("nvn.obj",
                            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                            "f 1/1/1 2/2/1 3/3/1\nf 2//4 4//4 3//4\n");
    scene::Scene s;
    std::vector<Diagnostic> warnings;
    Diagnostics diag([&](const Diagnostic& d) { warnings.push_back(d); });
    import_obj(obj, s, Transform{}, -1, diag);
    ASSERT_EQ(s.meshes.size(), 1u);
    const scene::Mesh& m = s.meshes[0];
    ASSERT_EQ(m.faces.size(), 2u);
    EXPECT_TRUE(m.normals.empty());
    for (const scene::MeshFace& f : m.faces) EXPECT_EQ(f.n[0], -1);
    EXPECT_GE(m.faces[0].uv[0], 0);  // the uvs stay
    EXPECT_EQ(m.faces[1].uv[0], -1);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].loc.line, 8);
    EXPECT_NE(warnings[0].message.find("defines no 'vn'"), std::string::npos);
    // A file that defines normals still may not name one past them.
    std::string bad = write("bad_vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n");
    scene::Scene s2;
    EXPECT_THROW(import_obj(bad, s2, Transform{}, -1, diag), Error);
}

TEST_F(ObjImporter, ZeroIndexIsAnErrorAtItsLine) {
    std::string obj = write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
    scene::Scene s;
    Diagnostics diag;
    try {
        import_obj(obj, s, Transform{}, -1, diag);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Scene);
        EXPECT_EQ(e.loc().line, 4);
    }
}

TEST_F(ObjImporter, MissingFileIsMissingFile) {
    scene::Scene s;
    Diagnostics diag;
    try {
        import_obj((dir_ / "nope.obj").string(), s, Transform{}, -1, diag);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::MissingFile);
    }
}

TEST_F(ObjImporter, ViewerFramesTheModel) {
    std::string obj = write("v.obj", "v -1 -1 0\nv 3 -1 0\nv 1 2 0\nf 1 2 3\n");
    Diagnostics diag;
    scene::Scene s = viewer_scene(obj, 320, 240, diag);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.lights.size(), 3u);
    // The camera looks at the bounds' centre (1, 0.5, 0).
    Vec3 to_centre = normalize(Vec3(1, 0.5, 0) - s.camera.location);
    EXPECT_NEAR(dot(to_centre, normalize(s.camera.direction)), 1.0, 1e-12);
}

TEST_F(ObjImporter, PovSceneKeywordPlacesTheModelAndOverridesItsTexture) {
    write("m.mtl", kMtl);
    write("a.obj", kTwoObjects);
    std::string pov = write("s.pov", R"(#version 3.7;
obj_file { "a.obj" translate <1, 0, 0> }
obj_file { "a.obj" texture { pigment { rgb <0, 0, 1> } } }
)");
    Diagnostics diag;
    pov::ParseOptions options;
    scene::Scene s = pov::parse_file(pov, options, diag);
    ASSERT_EQ(s.objects.size(), 2u);
    const auto* first = std::get_if<scene::Csg>(&s.objects[0].shape);
    ASSERT_NE(first, nullptr);
    ASSERT_EQ(first->children.size(), 2u);  // Quad and Tri
    // z mirrored (OBJ's right-handed axes), then the scene's translate.
    auto world = [&](const Vec3& p) {
        return s.objects[0].transform.point(first->children[0].transform.point(p));
    };
    EXPECT_DOUBLE_EQ(world(Vec3(0, 0, 2)).z, -2.0);
    EXPECT_DOUBLE_EQ(world(Vec3(0, 0, 0)).x, 1.0);
    // The first keeps the MTL's per-face materials; the override clears them.
    const auto& mesh0 = s.meshes[std::get<scene::MeshRef>(first->children[0].shape).mesh];
    EXPECT_GE(mesh0.faces[0].material, 0);
    const auto* second = std::get_if<scene::Csg>(&s.objects[1].shape);
    ASSERT_NE(second, nullptr);
    for (const auto& c : second->children) {
        const auto& mesh = s.meshes[std::get<scene::MeshRef>(c.shape).mesh];
        for (const auto& f : mesh.faces) EXPECT_EQ(f.material, -1);
    }
    EXPECT_DOUBLE_EQ(s.materials[s.objects[1].material].texture.pigment.color.rgb.b, 1.0);
}

// The materials of one imported OBJ by name.
std::map<std::string, const scene::Material*> by_name(const scene::Scene& s, const ObjImport& im) {
    std::map<std::string, const scene::Material*> out;
    for (int i = 0; i < im.object_count; ++i) {
        const scene::Object& o = s.objects[im.first_object + i];
        const auto& mesh = s.meshes[std::get<scene::MeshRef>(o.shape).mesh];
        out[o.name] = &s.materials[mesh.faces[0].material];
    }
    return out;
}

void expect_color(const Color& c, double r, double g, double b) {
    EXPECT_NEAR(c.r, r, 1e-6);
    EXPECT_NEAR(c.g, g, 1e-6);
    EXPECT_NEAR(c.b, b, 1e-6);
}

// tests/data/obj/principled.* were written by Blender 3.4.1's exporter from the Principled
// values in make_principled.py; each object carries the material of its name.
TEST_F(ObjImporter, BlenderPrincipledRoundTripWithPbrExtensions) {
    scene::Scene s;
    Diagnostics diag;
    const std::string dir = std::string(GLINT_SOURCE_DIR) + "/tests/data/obj/";
    ObjImport im = import_obj(dir + "principled.obj", s, Transform{}, -1, diag);
    EXPECT_TRUE(diag.all().empty());
    auto m = by_name(s, im);
    ASSERT_EQ(m.size(), 6u);
    const scene::Pbr& plastic = m["Plastic"]->pbr;
    expect_color(plastic.base_color, 0.8, 0.2, 0.1);
    EXPECT_NEAR(plastic.metallic, 0.0, 1e-6);
    EXPECT_NEAR(plastic.roughness, 0.3, 1e-6);
    EXPECT_NEAR(plastic.ior, 1.6, 1e-6);
    EXPECT_NEAR(plastic.specular, 0.4, 1e-6);
    EXPECT_NEAR(plastic.transmission, 0.0, 1e-6);
    EXPECT_NEAR(plastic.alpha, 1.0, 1e-6);
    EXPECT_TRUE((plastic.emission * plastic.emission_strength).is_black());
    const scene::Pbr& metal = m["Metal"]->pbr;
    expect_color(metal.base_color, 0.9, 0.6, 0.2);
    EXPECT_NEAR(metal.metallic, 1.0, 1e-6);
    EXPECT_NEAR(metal.roughness, 0.15, 1e-6);
    // Blender writes Tf = Transmission with illum 2: the PBR extension makes it count.
    const scene::Pbr& glass = m["Glass"]->pbr;
    EXPECT_NEAR(glass.transmission, 1.0, 1e-6);
    EXPECT_NEAR(glass.roughness, 0.05, 1e-6);
    EXPECT_NEAR(glass.ior, 1.5, 1e-6);
    EXPECT_NEAR(glass.metallic, 0.0, 1e-6);
    // Ke is Emission * Emission Strength (1, 0.5, 0.25) * 4.
    const scene::Pbr& lamp = m["Lamp"]->pbr;
    expect_color(lamp.emission * lamp.emission_strength, 4, 2, 1);
    expect_color(lamp.base_color, 0.1, 0.1, 0.1);
    const scene::Pbr& cutout = m["Cutout"]->pbr;
    EXPECT_NEAR(cutout.alpha, 0.4, 1e-6);
    EXPECT_NEAR(cutout.transmission, 0.0, 1e-6);  // illum 9 without Tf: alpha only
    EXPECT_NEAR(cutout.ior, 1.45, 1e-6);
    // Linked sockets become maps (Blender writes the first Mapping node's -o/-s on all).
    const scene::Pbr& tex = m["Textured"]->pbr;
    for (const scene::PbrMap* map : {&tex.base_color_map, &tex.metallic_map, &tex.roughness_map,
                                     &tex.emission_map, &tex.alpha_map, &tex.bump_map}) {
        EXPECT_TRUE(map->present()) << map->file;
        EXPECT_NEAR(map->offset.x, 0.25, 1e-6);
        EXPECT_NEAR(map->offset.y, 0.5, 1e-6);
        EXPECT_NEAR(map->scale.x, 2, 1e-6);
        EXPECT_NEAR(map->scale.y, 3, 1e-6);
    }
    EXPECT_EQ(tex.base_color_map.file, "tint.png");
    EXPECT_EQ(tex.roughness_map.file, "ramp_gray.png");
    EXPECT_EQ(tex.bump_map.file, "flat_normal.png");
    EXPECT_NEAR(tex.bump_map.bump_multiplier, 0.7, 1e-6);  // the Normal Map's Strength
    EXPECT_FALSE(tex.exponent_map.present());
    EXPECT_NEAR(tex.specular, 0.5, 1e-6);
}

TEST_F(ObjImporter, BlenderPrincipledRoundTripWithoutPbrExtensions) {
    scene::Scene s;
    Diagnostics diag;
    const std::string dir = std::string(GLINT_SOURCE_DIR) + "/tests/data/obj/";
    ObjImport im = import_obj(dir + "principled_classic.obj", s, Transform{}, -1, diag);
    auto m = by_name(s, im);
    ASSERT_EQ(m.size(), 6u);
    // Ns = 1000 (1 - roughness)^2 inverted; metallic from Ka under illum 3 (Blender writes
    // Ka 1 for metallic 0 too, with illum 2).
    EXPECT_NEAR(m["Plastic"]->pbr.roughness, 0.3, 1e-6);
    EXPECT_NEAR(m["Plastic"]->pbr.metallic, 0.0, 1e-6);
    EXPECT_NEAR(m["Metal"]->pbr.roughness, 0.15, 1e-6);
    EXPECT_NEAR(m["Metal"]->pbr.metallic, 1.0, 1e-6);
    EXPECT_NEAR(m["Glass"]->pbr.roughness, 0.05, 1e-6);
    EXPECT_NEAR(m["Glass"]->pbr.transmission, 0.0, 1e-6);  // not written without PBR
    EXPECT_NEAR(m["Cutout"]->pbr.alpha, 0.4, 1e-6);
    EXPECT_NEAR(m["Cutout"]->pbr.metallic, 0.0, 1e-6);  // illum 9: Ka is not metallic
    expect_color(m["Lamp"]->pbr.emission * m["Lamp"]->pbr.emission_strength, 4, 2, 1);
    // Blender's roughness image is map_Ns and its metallic image map_refl here.
    const scene::Pbr& tex = m["Textured"]->pbr;
    EXPECT_EQ(tex.roughness_map.file, "ramp_gray.png");
    EXPECT_TRUE(tex.roughness_map.present());
    EXPECT_EQ(tex.metallic_map.file, "ramp_gray.png");
    EXPECT_FALSE(tex.exponent_map.present());
}

TEST_F(ObjImporter, TfIsTransmissionOnlyForRefractingIllumOrPbr) {
    write("t.mtl", R"(newmtl opaque
Kd 0.5 0.5 0.5
Tf 1 1 1
illum 2
newmtl glass
Tf 0.6 0.6 0.6
illum 4
newmtl pbr
Tf 0.5 0.5 0.5
illum 2
Pr 0
newmtl classic_glass7
Tf 1 1 1
illum 7
)");
    std::string obj = write("t.obj", R"(mtllib t.mtl
v 0 0 0
v 1 0 0
v 0 1 0
o opaque
usemtl opaque
f 1 2 3
o glass
usemtl glass
f 1 2 3
o pbr
usemtl pbr
f 1 2 3
o classic_glass7
usemtl classic_glass7
f 1 2 3
)");
    scene::Scene s;
    Diagnostics diag;
    auto m = by_name(s, import_obj(obj, s, Transform{}, -1, diag));
    EXPECT_EQ(m["opaque"]->pbr.transmission, 0.0);
    EXPECT_EQ(m["opaque"]->texture.pigment.color.filter, 0.0);  // Whitted: no filter either
    EXPECT_NEAR(m["glass"]->pbr.transmission, 0.6, 1e-6);
    EXPECT_NEAR(m["glass"]->pbr.ior, 1.5, 1e-6);  // no Ni under a refracting illum: 1.5
    EXPECT_NEAR(m["pbr"]->pbr.transmission, 0.5, 1e-6);
    EXPECT_NEAR(m["pbr"]->pbr.roughness, 0.0, 1e-12);  // `Pr 0` is given, not "absent"
    EXPECT_NEAR(m["opaque"]->pbr.ior, 1.45, 1e-6);
    EXPECT_NEAR(m["classic_glass7"]->pbr.transmission, 1.0, 1e-6);
}

TEST_F(ObjImporter, EveryMapGoesToItsSlotAndMissingOnesAreNamed) {
    std::ofstream(dir_ / "here.png") << "not read by the importer";
    write("maps.mtl", R"(newmtl all
map_Kd here.png
map_Ks -s 2 2 1 here.png
map_Ke -o 0.5 0 0 here.png
map_Ns here.png
map_d gone_d.png
map_Pr here.png
map_Pm here.png
bump -bm 0.25 here.png
map_refl here.png
)");
    std::string obj = write("maps.obj", "mtllib maps.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                        "o all\nusemtl all\nf 1 2 3\n");
    scene::Scene s;
    Diagnostics diag;
    auto m = by_name(s, import_obj(obj, s, Transform{}, -1, diag));
    const scene::Pbr& p = m["all"]->pbr;
    EXPECT_TRUE(p.base_color_map.present());
    EXPECT_TRUE(p.specular_map.present());
    EXPECT_NEAR(p.specular_map.scale.x, 2, 1e-12);
    EXPECT_TRUE(p.emission_map.present());
    EXPECT_NEAR(p.emission_map.offset.x, 0.5, 1e-12);
    EXPECT_TRUE(p.exponent_map.present());  // not Blender's file: map_Ns is an exponent
    EXPECT_TRUE(p.roughness_map.present());
    EXPECT_TRUE(p.metallic_map.present());  // map_Pm, not map_refl
    EXPECT_TRUE(p.bump_map.present());
    EXPECT_NEAR(p.bump_map.bump_multiplier, 0.25, 1e-12);
    EXPECT_FALSE(p.alpha_map.present());
    int named = 0;
    for (const auto& d : diag.all())
        named += d.message.find("texture 'gone_d.png' not found") != std::string::npos;
    EXPECT_EQ(named, 1);
    // Without its image the material keeps Blender's default base color.
    EXPECT_NEAR(p.base_color.r, 0.8, 1e-12);
}

TEST_F(ObjImporter, KaIsMetallicUnderReflectingIllumOnly) {
    MtlValues v;
    v.has_Ka = true;
    v.Ka = Color(0.7, 0.7, 0.7);
    v.illum = 3;
    EXPECT_NEAR(material_from_mtl(v).pbr.metallic, 0.7, 1e-12);
    v.illum = 2;
    EXPECT_NEAR(material_from_mtl(v).pbr.metallic, 0.0, 1e-12);
    v.illum = 3;
    v.has_Pm = true;
    v.Pm = 0;
    EXPECT_NEAR(material_from_mtl(v).pbr.metallic, 0.0, 1e-12);  // Pm wins, even 0
}

}  // namespace
}  // namespace glint::obj
