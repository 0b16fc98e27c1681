#include "render/mesh_camera.h"

#include <algorithm>
#include <cmath>

namespace glint::render {

MeshCameraRays::MeshCameraRays(const scene::MeshCamera& camera,
                               const std::vector<scene::Mesh>& meshes, double offset,
                               bool reverse)
    : rays_(std::max(1, camera.rays_per_pixel)),
      distribution_(camera.distribution),
      max_distance_(camera.max_distance),
      smooth_(camera.smooth),
      offset_(offset),
      reverse_(reverse) {
    size_t total = 0;
    for (const scene::MeshCameraMesh& m : camera.meshes) {
        Part part;
        part.transform = m.transform;
        if (m.mesh >= 0 && static_cast<size_t>(m.mesh) < meshes.size()) {
            const scene::Mesh& mesh = meshes[static_cast<size_t>(m.mesh)];
            for (const scene::MeshFace& mf : mesh.faces) {
                Face f;
                bool ok = true;
                for (int k = 0; k < 3; ++k) {
                    const int v = mf.v[static_cast<size_t>(k)];
                    if (v < 0 || static_cast<size_t>(v) >= mesh.positions.size()) ok = false;
                    else f.p[static_cast<size_t>(k)] = mesh.positions[static_cast<size_t>(v)];
                }
                if (!ok) continue;
                const Vec3 c = cross(f.p[2] - f.p[0], f.p[1] - f.p[0]);
                const double len = length(c);
                if (len == 0.0 || !std::isfinite(len)) continue;  // POV-Ray drops it
                f.normal = c / len;
                f.has_uv = true;
                for (int k = 0; k < 3; ++k) {
                    const size_t ks = static_cast<size_t>(k);
                    const int ni = mf.n[ks], ti = mf.uv[ks];
                    f.n[ks] = ni >= 0 && static_cast<size_t>(ni) < mesh.normals.size()
                                  ? mesh.normals[static_cast<size_t>(ni)]
                                  : f.normal;
                    if (ti >= 0 && static_cast<size_t>(ti) < mesh.uvs.size())
                        f.uv[ks] = mesh.uvs[static_cast<size_t>(ti)];
                    else
                        f.has_uv = false;
                }
                part.faces.push_back(f);
            }
        }
        total += part.faces.size();
        summed_.push_back(total);
        parts_.push_back(std::move(part));
    }
}

std::optional<Ray> MeshCameraRays::from_face(const Part& part, const Face& f) const {
    Ray ray;
    const Vec3 centroid = (f.p[0] + f.p[1] + f.p[2]) * (1.0 / 3.0);
    ray.dir = f.normal;
    ray.origin = centroid + ray.dir * offset_;
    if (reverse_) ray.dir = -ray.dir;
    ray.origin = part.transform.point(ray.origin);
    ray.dir = normalize(part.transform.normal(ray.dir));
    if (max_distance_ > 1e-10) ray.tmax = max_distance_;
    return ray;
}

std::optional<Ray> MeshCameraRays::generate(double x, double y, int ray_number, double width,
                                            double height) const {
    if (parts_.empty()) return std::nullopt;
    // POV-Ray's raster position (it moves glint's pixel centres by +0.5 in x and -0.5 in y,
    // as Camera::screen notes, so its first two rows share a face row), clipped to the image,
    // then taken as whole pixels.
    x += 0.5;
    y -= 0.5;
    x = std::max(0.0, std::min(x, width - 1.0));
    y = std::max(0.0, std::min(y, height - 1.0));
    const auto ux = static_cast<unsigned>(x), uy = static_cast<unsigned>(y);
    const auto uw = static_cast<unsigned>(width);
    switch (distribution_) {
        case 0: {
            const Part& part = parts_[static_cast<size_t>(std::min<int>(
                ray_number, static_cast<int>(parts_.size()) - 1))];
            const size_t face = static_cast<size_t>(uy) * uw + ux;
            if (face >= part.faces.size()) return std::nullopt;
            return from_face(part, part.faces[face]);
        }
        case 1: {
            // The meshes' faces summed; ray k of a pixel takes face pixel + k x all faces
            // (tracepixel.cpp adds the face count, so only the first ray finds one).
            const size_t all = summed_.back();
            const size_t face = static_cast<size_t>(uy) * uw + ux +
                                static_cast<size_t>(ray_number) * all;
            if (face >= all) return std::nullopt;
            size_t first = 0;
            for (size_t m = 0; m < parts_.size(); first = summed_[m++])
                if (summed_[m] > face) return from_face(parts_[m], parts_[m].faces[face - first]);
            return std::nullopt;
        }
        case 2: {
            // Side by side, the first mesh leftmost; the face index keeps the whole image's x
            // (as tracepixel.cpp computes it).
            const size_t n = parts_.size();
            const auto m = static_cast<size_t>(x / (width / static_cast<double>(n)));
            if (m >= n) return std::nullopt;
            const size_t face = static_cast<size_t>(uy) * (uw / n) + ux;
            if (face >= parts_[m].faces.size()) return std::nullopt;
            return from_face(parts_[m], parts_[m].faces[face]);
        }
        default: {
            // The first face of the first mesh whose uv triangle holds the pixel's uv.
            const double u = (x - 0.5) / width;
            const double v = 1.0 - (y + 0.5) / height;
            const Part& part = parts_[0];
            for (const Face& f : part.faces) {
                if (!f.has_uv) continue;
                const Vec2 &a = f.uv[0], &b = f.uv[1], &c = f.uv[2];
                const double scale = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
                const double b1 = ((b.x - u) * (c.y - v) - (c.x - u) * (b.y - v)) / scale;
                const double b2 = ((c.x - u) * (a.y - v) - (a.x - u) * (c.y - v)) / scale;
                const double b3 = ((a.x - u) * (b.y - v) - (b.x - u) * (a.y - v)) / scale;
                if (b1 < 0 || b2 < 0 || b3 < 0) continue;
                Ray ray;
                ray.origin = f.p[0] * b1 + f.p[1] * b2 + f.p[2] * b3;
                ray.dir = smooth_ ? f.n[0] * b1 + f.n[1] * b2 + f.n[2] * b3 : f.normal;
                ray.origin = ray.origin + ray.dir * offset_;
                if (reverse_) ray.dir = -ray.dir;
                ray.origin = part.transform.point(ray.origin);
                ray.dir = part.transform.normal(ray.dir);
                if (!(length_squared(ray.dir) > 0)) return std::nullopt;
                ray.dir = normalize(ray.dir);
                if (max_distance_ > 1e-10) ray.tmax = max_distance_;
                return ray;
            }
            return std::nullopt;
        }
    }
}

}  // namespace glint::render
