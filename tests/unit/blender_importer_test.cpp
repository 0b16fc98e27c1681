// formats/blender: the add-on's exchange read into the IR, and its errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "formats/blender/blender_importer.h"

namespace glint::blender {
namespace {

namespace fs = std::filesystem;

// Writes a scene folder: the JSON text and a buffer of one quad (two triangles).
class Exchange {
public:
    Exchange() {
        dir_ = fs::temp_directory_path() / ("glint_bl_" + std::to_string(::getpid()) + "_" +
                                            std::to_string(counter_++));
        fs::create_directories(dir_);
        const float pos[] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
        const uint32_t loops[] = {0, 1, 2, 3};
        const uint32_t tris[] = {0, 1, 2, 0, 2, 3};
        const float normals[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
        const uint8_t smooth[] = {1, 0, 0, 0};  // two triangles, padded to 4 bytes
        const uint16_t slots[] = {0, 1};
        append(pos, sizeof pos);       // 0: 48 bytes
        append(loops, sizeof loops);   // 48: 16
        append(tris, sizeof tris);     // 64: 24
        append(normals, sizeof normals);  // 88: 48
        append(smooth, sizeof smooth);  // 136: 4
        append(slots, sizeof slots);   // 140: 4
    }
    ~Exchange() { fs::remove_all(dir_); }

    std::string write(const std::string& json) {
        std::ofstream(dir_ / "scene.bin", std::ios::binary)
            .write(reinterpret_cast<const char*>(bin_.data()), static_cast<std::streamsize>(bin_.size()));
        const fs::path p = dir_ / "scene.json";
        std::ofstream(p) << json;
        return p.string();
    }

    static std::string quad_mesh() {
        return R"({"name": "Quad",
          "positions": {"offset": 0, "count": 4, "type": "f32", "components": 3},
          "loop_vertex": {"offset": 48, "count": 4, "type": "u32"},
          "triangles": {"offset": 64, "count": 2, "type": "u32", "components": 3},
          "normals": {"offset": 88, "count": 4, "type": "f32", "components": 3},
          "smooth": {"offset": 136, "count": 2, "type": "u8"},
          "material_index": {"offset": 140, "count": 2, "type": "u16"}})";
    }

    static std::string scene(const std::string& objects, const std::string& extra = "") {
        return R"({"format": "glint-blender", "version": 1, "buffers": "scene.bin",
          "render": {"width": 32, "height": 24, "samples": 4},
          "camera": {"type": "PERSP", "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,5, 0,0,0,1],
                     "lens": 50, "sensor_width": 36},
          "meshes": [)" + quad_mesh() + R"(],
          "materials": [{"name": "Red", "graph": {"output": 0, "nodes": [
              {"type": "ShaderNodeOutputMaterial", "name": "Material Output",
               "inputs": [{"id": "Surface", "type": "SHADER", "link": [1, "BSDF"]}]},
              {"type": "ShaderNodeBsdfDiffuse", "name": "Diffuse BSDF",
               "inputs": [{"id": "Color", "type": "RGBA", "value": [0.8, 0.1, 0.1, 1]}],
               "outputs": [{"id": "BSDF", "type": "SHADER"}]}]}},
            {"name": "Blue"}],
          "objects": [)" + objects + "]" + extra + "}";
    }

private:
    void append(const void* p, size_t n) {
        const auto* b = static_cast<const unsigned char*>(p);
        bin_.insert(bin_.end(), b, b + n);
        while (bin_.size() % 4) bin_.push_back(0);
    }
    static inline int counter_ = 0;
    fs::path dir_;
    std::vector<unsigned char> bin_;
};

std::string object(double x, const std::string& materials = "[0, 1]") {
    return R"({"name": "Q", "mesh": 0, "materials": )" + materials +
           R"(, "matrix": [1,0,0,)" + std::to_string(x) + R"(, 0,1,0,0, 0,0,1,0, 0,0,0,1]})";
}

scene::Scene load(const std::string& path, Diagnostics* diag = nullptr) {
    Diagnostics local;
    return import_blender(path, ImportLimits{}, diag ? *diag : local);
}

std::string error_of(const std::string& path) {
    try {
        load(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(BlenderImporter, InstancesShareOneMeshAndSlotsBecomeFaceMaterials) {
    Exchange ex;
    const std::string p = ex.write(Exchange::scene(object(0) + "," + object(3) + "," +
                                                   object(6, "[1, 0]")));
    const scene::Scene s = load(p);
    ASSERT_EQ(s.objects.size(), 3u);
    // Two objects with the same slots share a mesh; the third maps them the other way.
    ASSERT_EQ(s.meshes.size(), 2u);
    EXPECT_EQ(std::get<scene::MeshRef>(s.objects[0].shape).mesh,
              std::get<scene::MeshRef>(s.objects[1].shape).mesh);
    const scene::Mesh& m = s.meshes[std::get<scene::MeshRef>(s.objects[0].shape).mesh];
    ASSERT_EQ(m.faces.size(), 2u);
    EXPECT_NE(m.faces[0].material, m.faces[1].material);
    EXPECT_EQ(s.materials[m.faces[0].material].graph, 0);  // "Red" has the graph
    EXPECT_EQ(s.materials[m.faces[1].material].graph, -1);  // "Blue" has none
    // Smooth triangle 0 interpolates the corner normals; flat triangle 1 has none.
    EXPECT_GE(m.faces[0].n[0], 0);
    EXPECT_EQ(m.faces[1].n[0], -1);
    EXPECT_DOUBLE_EQ(s.objects[1].transform.point(Vec3(0, 0, 0)).x, 3);
    ASSERT_TRUE(s.blender_render.has_value());
    EXPECT_EQ(s.blender_render->samples, 4);
    EXPECT_FALSE(s.blender_render->adaptive_sampling);  // not written: off
    EXPECT_EQ(s.shader_graphs[0].nodes[1].type, "ShaderNodeBsdfDiffuse");
}

TEST(BlenderImporter, CameraFollowsBlendersSensorFit) {
    Exchange ex;
    const scene::Scene s = load(ex.write(Exchange::scene(object(0))));
    // 50 mm lens on a 36 mm sensor, landscape: the width spans 36 / 50 at unit distance.
    EXPECT_NEAR(length(s.camera.right), 36.0 / 50.0, 1e-9);
    EXPECT_NEAR(length(s.camera.up), 36.0 / 50.0 * 24 / 32, 1e-9);
    EXPECT_NEAR(s.camera.direction.z, -1, 1e-12);  // looks along its -Z
}

TEST(BlenderImporter, CameraClipsAndWorldVolumeSettingsAreRead) {
    Exchange ex;
    std::string json = Exchange::scene(
        object(0), R"(, "world": {"color": [0, 0, 0], "graph": {"output": 0, "nodes": [
              {"type": "ShaderNodeOutputWorld", "name": "World Output", "inputs": []}]},
            "cycles": {"volume_step_size": 0.25, "homogeneous_volume": true}})");
    const std::string lens = R"("lens": 50,)";
    json.replace(json.find(lens), lens.size(), lens + R"( "clip_start": 0.5, "clip_end": 40,)");
    const scene::Scene s = load(ex.write(json));
    EXPECT_DOUBLE_EQ(s.camera.clip_start, 0.5);
    EXPECT_DOUBLE_EQ(s.camera.clip_end, 40);
    EXPECT_DOUBLE_EQ(s.world_volume_step, 0.25);
    EXPECT_TRUE(s.world_volume_homogeneous);
    // Without them: no clipping, Cycles' defaults.
    const scene::Scene d = load(ex.write(Exchange::scene(object(0))));
    EXPECT_EQ(d.camera.clip_start, 0);
    EXPECT_TRUE(std::isinf(d.camera.clip_end));
    EXPECT_DOUBLE_EQ(d.world_volume_step, 1.0);
    EXPECT_FALSE(d.world_volume_homogeneous);
}

TEST(BlenderImporter, PanoramicCameraCarriesCyclesSettings) {
    Exchange ex;
    std::string json = Exchange::scene(object(0));
    const std::string persp = R"("type": "PERSP", "matrix")";
    const size_t at = json.find(persp);
    ASSERT_NE(at, std::string::npos);
    json.replace(at, persp.size(),
                 R"("type": "PANO", "panorama_type": "FISHEYE_EQUISOLID", "fisheye_lens": 8,
                    "fisheye_fov": 3.0, "sensor_fit": "AUTO", "sensor_height": 24,
                    "latitude_min": -1, "longitude_max": 2, "matrix")");
    const scene::Scene s = load(ex.write(json));
    EXPECT_EQ(s.camera.kind, scene::CameraKind::BlenderPanorama);
    const scene::Panorama& p = s.camera.panorama;
    EXPECT_EQ(p.type, scene::PanoramaType::FisheyeEquisolid);
    EXPECT_DOUBLE_EQ(p.lens, 8);
    EXPECT_DOUBLE_EQ(p.fov, 3.0);
    EXPECT_DOUBLE_EQ(p.latitude_min, -1);
    EXPECT_DOUBLE_EQ(p.longitude_max, 2);
    // 32 x 24 pixels, AUTO fit: the 36 mm sensor spans the width, the height is fitted to it.
    EXPECT_DOUBLE_EQ(p.sensor_width, 36);
    EXPECT_DOUBLE_EQ(p.sensor_height, 27);
    EXPECT_NEAR(s.camera.direction.z, -1, 1e-12);  // the frame: looks along its -Z
    EXPECT_NEAR(length(s.camera.right), 1, 1e-12);

    std::string bad = json;
    bad.replace(bad.find("FISHEYE_EQUISOLID"), 17, "STEREOGRAPHIC");
    EXPECT_NE(error_of(ex.write(bad)).find("camera.panorama_type"), std::string::npos)
        << error_of(ex.write(bad));
}

// `text` with the first `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

TEST(BlenderImporter, AdaptiveSamplingSettingsAreRead) {
    Exchange ex;
    const std::string text = replaced(
        Exchange::scene(object(0)), "\"samples\": 4",
        "\"samples\": 4, \"adaptive_sampling\": {\"use\": true, \"threshold\": 0.05, "
        "\"min_samples\": 12}");
    const scene::Scene s = load(ex.write(text));
    ASSERT_TRUE(s.blender_render.has_value());
    EXPECT_TRUE(s.blender_render->adaptive_sampling);
    EXPECT_DOUBLE_EQ(s.blender_render->adaptive_threshold, 0.05);
    EXPECT_EQ(s.blender_render->adaptive_min_samples, 12);
}

TEST(BlenderImporter, ErrorsNameTheJsonPath) {
    Exchange ex;
    const std::string scene = Exchange::scene(object(0));
    const std::string bad = replaced(scene, "\"count\": 4, \"type\": \"u32\"",
                                     "\"count\": 400, \"type\": \"u32\"");
    EXPECT_NE(error_of(ex.write(bad)).find("meshes[0].loop_vertex: the view"), std::string::npos);

    const std::string link = replaced(scene, "[1, \"BSDF\"]", "[1, \"Nope\"]");
    EXPECT_NE(error_of(ex.write(link)).find("has no such output"), std::string::npos);

    const std::string mesh = replaced(scene, "\"mesh\": 0", "\"mesh\": 7");
    EXPECT_NE(error_of(ex.write(mesh)).find("objects[0].mesh: no mesh 7"), std::string::npos);

    EXPECT_NE(error_of(ex.write("{\"format\": \"glint-blender\", \"version\": 2}"))
                  .find("version 2 is not supported"),
              std::string::npos);
}

TEST(BlenderImporter, JsonSyntaxErrorsGiveLineAndColumn) {
    Exchange ex;
    const std::string p = ex.write("{\n  \"format\": \"glint-blender\",\n  \"version\": 1,,\n}");
    try {
        load(p);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.loc().line, 3);
        EXPECT_NE(std::string(e.what()).find("JSON syntax"), std::string::npos);
    }
}

TEST(BlenderImporter, ObjectsScaledToNothingAreLeftOut) {
    Exchange ex;
    const std::string flat = R"({"name": "Z", "mesh": 0, "materials": [0],
        "matrix": [0,0,0,0, 0,0,0,0, 0,0,0,0, 0,0,0,1]})";
    const scene::Scene s = load(ex.write(Exchange::scene(object(0) + "," + flat)));
    EXPECT_EQ(s.objects.size(), 1u);
}

TEST(BlenderImporter, MotionIsReadOnlyWithMotionBlurOn) {
    Exchange ex;
    const std::string moving = R"({"name": "M", "mesh": 0, "materials": [0],
        "matrix": [1,0,0,1, 0,1,0,0, 0,0,1,0, 0,0,0,1],
        "motion": [[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1], [1,0,0,1, 0,1,0,0, 0,0,1,0, 0,0,0,1],
                   [1,0,0,2, 0,1,0,0, 0,0,1,0, 0,0,0,1]]})";
    // The camera's matrices carry a scale of 2, which Cycles clears.
    const std::string camera_motion =
        R"("motion": [[2,0,0,0, 0,2,0,0, 0,0,2,5, 0,0,0,1], [2,0,0,3, 0,2,0,0, 0,0,2,5, 0,0,0,1]],
           "lens": 50)";
    std::string text = replaced(Exchange::scene(object(0) + "," + moving), "\"lens\": 50",
                                camera_motion);
    const std::string on = replaced(text, "\"samples\": 4",
                                    "\"samples\": 4, \"motion_blur\": {\"use\": true}");
    const scene::Scene s = load(ex.write(on));
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_TRUE(s.objects[0].motion.empty());
    ASSERT_EQ(s.objects[1].motion.size(), 3u);
    EXPECT_EQ(s.objects[1].motion[2].m[0][3], 2);
    ASSERT_EQ(s.camera.motion.size(), 2u);
    EXPECT_DOUBLE_EQ(s.camera.motion[1].m[0][0], 1);  // scale cleared
    EXPECT_DOUBLE_EQ(s.camera.motion[1].m[0][3], 3);
    EXPECT_DOUBLE_EQ(s.camera.centre.m[2][3], 5);
    // Off (or absent): the matrices are ignored and the scene renders still.
    const scene::Scene off = load(ex.write(text));
    EXPECT_TRUE(off.objects[1].motion.empty());
    EXPECT_TRUE(off.camera.motion.empty());
    // One matrix is not a motion.
    const std::string lone = R"({"name": "L", "mesh": 0, "materials": [0],
        "matrix": [1,0,0,1, 0,1,0,0, 0,0,1,0, 0,0,0,1],
        "motion": [[1,0,0,1, 0,1,0,0, 0,0,1,0, 0,0,0,1]]})";
    const std::string err = error_of(ex.write(replaced(
        Exchange::scene(object(0) + "," + lone), "\"samples\": 4",
        "\"samples\": 4, \"motion_blur\": {\"use\": true}")));
    EXPECT_NE(err.find("objects[1].motion: expected two or more"), std::string::npos) << err;
}

}  // namespace
}  // namespace glint::blender
