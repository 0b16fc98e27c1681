// OBJ/MTL import (formats/obj): structure, the MTL -> material mapping of MTL.md, and broken
// input reported with file:line:col.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

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

}  // namespace
}  // namespace glint::obj
