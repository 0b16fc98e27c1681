// POV-Ray 3.7's mesh_camera (scene::MeshCamera; tracepixel.cpp, CreateCameraRay): the faces
// of the camera's meshes, flattened once, and the ray of a raster position and ray number.
// Faces POV-Ray drops as degenerate (a zero cross product) are left out here too, so the
// pixel-to-face numbering is POV-Ray's.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "render/ray.h"
#include "scene/camera.h"
#include "scene/mesh.h"

namespace glint::render {

class MeshCameraRays {
public:
    // `meshes`: the scene's (scene::MeshCamera::meshes index into them); `offset` the
    // camera location's z, `reverse` a negative direction z.
    MeshCameraRays(const scene::MeshCamera& camera, const std::vector<scene::Mesh>& meshes,
                   double offset, bool reverse);
    int rays_per_pixel() const { return rays_; }
    // The ray for raster position (x, y) (integers: pixel centres) of a width x height image;
    // none where no face belongs to it (POV-Ray leaves the pixel black). POV-Ray's position is
    // (x + 0.5, y - 0.5): pixel row y > 0 takes the faces of row y - 1, and row 0 those of
    // row 0 too.
    std::optional<Ray> generate(double x, double y, int ray_number, double width,
                                double height) const;

private:
    struct Face {
        std::array<Vec3, 3> p;
        std::array<Vec3, 3> n;   // vertex normals (smooth), else the face normal thrice
        std::array<Vec2, 3> uv;
        Vec3 normal;             // POV-Ray's face normal: (P3 - P1) x (P2 - P1), unit
        bool has_uv = false;
    };
    struct Part {
        std::vector<Face> faces;
        Transform transform;
    };
    std::optional<Ray> from_face(const Part& part, const Face& f) const;

    std::vector<Part> parts_;
    std::vector<size_t> summed_;  // distribution 1: faces up to and including each part
    int rays_ = 1;
    int distribution_ = 0;
    double max_distance_ = 0;
    bool smooth_ = false;
    double offset_ = 0;
    bool reverse_ = false;
};

}  // namespace glint::render
