// POV-Ray's mesh_camera (render/mesh_camera.h): rays from the faces' centroids along their
// normals by pixel index (distributions 0-2), from uv coordinates (3), the location's z as an
// offset along the normal and a negative direction z reversing the rays, the mesh's transform,
// degenerate faces left out of the numbering as POV-Ray leaves them, and POV-Ray's errors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render/camera.h"
#include "render/render.h"
#include "unit/pov_test_util.h"

namespace glint::render {
namespace {

// Two triangles in the z = 0 plane (a unit square), one degenerate between them, uvs
// covering [0, 1]^2 the same way.
const char* kMesh =
    "#declare M = mesh2 {\n"
    "  vertex_vectors { 5, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0>, <2,2,0> }\n"
    "  uv_vectors { 5, <0,0>, <1,0>, <1,1>, <0,1>, <1,1> }\n"
    "  face_indices { 3, <0,1,2>, <0,0,4>, <0,2,3> }\n"
    "}\n";

scene::Scene scene_with(const std::string& camera) {
    return pov::testing::parse(std::string("#version 3.7;\n") + kMesh + camera +
                               "sphere { 0, 1 pigment { rgb 1 } }\n");
}

TEST(MeshCamera, FacesByPixelFromCentroidsAlongNormals) {
    const scene::Scene s =
        scene_with("camera { mesh_camera { 1 0 mesh { M translate <0, 0, 5> } } "
                   "location <0, 0, 0.25> }\n");
    ASSERT_EQ(s.camera.kind, scene::CameraKind::Mesh);
    const Camera cam(s.camera, 4, 2, &s.meshes);
    // Face 0 (<0,0,0>, <1,0,0>, <1,1,0>): POV-Ray's normal is (P3 - P1) x (P2 - P1) = -z.
    std::optional<Ray> r = cam.generate(0, 0);
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->origin.x, 2.0 / 3, 1e-12);
    EXPECT_NEAR(r->origin.y, 1.0 / 3, 1e-12);
    EXPECT_NEAR(r->origin.z, 5 - 0.25, 1e-12);  // moved 0.25 along the normal, then placed
    EXPECT_NEAR(r->dir.z, -1, 1e-12);
    // The degenerate face is not numbered: pixel 1 is the third face.
    r = cam.generate(1, 0);
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->origin.x, 1.0 / 3, 1e-12);
    EXPECT_NEAR(r->origin.y, 2.0 / 3, 1e-12);
    // Pixels past the faces trace nothing, and positions are clipped to the image. POV-Ray
    // takes row y - 1's faces for row y > 0 (its raster position is y - 0.5): row 1 repeats
    // row 0.
    EXPECT_FALSE(cam.generate(2, 0));
    EXPECT_NEAR(cam.generate(1, 1)->origin.x, 1.0 / 3, 1e-12);
    EXPECT_TRUE(cam.generate(-3, -3));
    const Camera tall(s.camera, 1, 3, &s.meshes);
    EXPECT_TRUE(tall.generate(0, 2));  // row 2 -> face 1
    EXPECT_NEAR(tall.generate(0, 2)->origin.y, 2.0 / 3, 1e-12);
}

TEST(MeshCamera, NegativeDirectionReversesAndUvFindsTheFace) {
    const scene::Scene s = scene_with(
        "camera { mesh_camera { 1 3 mesh { M } } direction <0, 0, -1> }\n");
    const Camera cam(s.camera, 10, 10, &s.meshes);
    // Pixel (7, 8): POV-Ray's position (7.5, 7.5), u = 7 / 10, v = 1 - 8 / 10: below the
    // diagonal, the first face.
    std::optional<Ray> r = cam.generate(7, 8);
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->origin.x, 0.7, 1e-12);
    EXPECT_NEAR(r->origin.y, 0.2, 1e-12);
    EXPECT_NEAR(r->dir.z, 1, 1e-12);  // reversed
    r = cam.generate(2, 1);  // u = 0.2, v = 0.9: the other face
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->origin.x, 0.2, 1e-12);
    EXPECT_NEAR(r->origin.y, 0.9, 1e-12);
}

TEST(MeshCamera, SideBySideMeshesAndRaysPerPixel) {
    const scene::Scene s = scene_with(
        "camera { mesh_camera { 1 2 mesh { M } mesh { M translate x * 10 } } }\n");
    const Camera cam(s.camera, 4, 1, &s.meshes);
    // The right half's mesh, with the whole image's x in its face index (as POV-Ray has it):
    // pixel 2 -> face 2 of the second mesh, which does not exist (its position is 2.5).
    ASSERT_TRUE(cam.generate(1, 0));
    EXPECT_NEAR(cam.generate(1, 0)->origin.x, 1.0 / 3, 1e-12);
    EXPECT_FALSE(cam.generate(2, 0));
    const scene::Scene two = scene_with(
        "camera { mesh_camera { 2 0 mesh { M } mesh { M translate y * 3 } } }\n");
    const Camera c2(two.camera, 2, 1, &two.meshes);
    EXPECT_EQ(c2.rays_per_pixel(), 2);
    EXPECT_NEAR(c2.generate(0, 0, 1)->origin.y, 3 + 1.0 / 3, 1e-12);
}

TEST(MeshCamera, PovRaysErrors) {
    using pov::testing::error_of;
    const std::string v = std::string("#version 3.7;\n") + kMesh;
    EXPECT_NE(error_of(v + "camera { mesh_camera { 0 0 mesh { M } } }").find("rays per pixel"),
              std::string::npos);
    EXPECT_NE(error_of(v + "camera { mesh_camera { 1 4 mesh { M } } }").find("distribution"),
              std::string::npos);
    EXPECT_NE(error_of(v + "camera { mesh_camera { 2 3 mesh { M } mesh { M } } }")
                  .find("must be 1 for distribution method #2 or #3"),
              std::string::npos);
    EXPECT_NE(error_of(v + "camera { mesh_camera { 2 0 mesh { M } } }")
                  .find("<= number of meshes"),
              std::string::npos);
    EXPECT_NE(error_of(v + "camera { mesh_camera { 1 0 mesh { M } smooth } }").find("smooth"),
              std::string::npos);
    EXPECT_NE(error_of(v + "camera { mesh_camera { 1 0 } }").find("expected mesh or mesh2"),
              std::string::npos);
}

}  // namespace
}  // namespace glint::render
