#include "render/shapes/mesh/motion_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/float.h"
#include "render/accel/bvh.h"
#include "render/shapes/mesh/mesh_shading.h"
#include "render/shapes/mesh/triangle.h"

namespace glint::render {
namespace {

// Unlike the still meshes' float leaves (mesh_prim.cpp), vertices stay in double per step and
// each candidate face is interpolated before the watertight test: deforming meshes are the
// few characters of a shot, not its million-triangle set, so this trades speed for plainness.
class MotionMeshPrim final : public Primitive, public AttributeSource {
public:
    MotionMeshPrim(const scene::Mesh& mesh, const std::vector<int>& faces)
        : positions_(mesh.motion_positions), normals_(mesh.motion_normals), uvs_(mesh.uvs) {
        faces_.reserve(faces.size());
        std::vector<Bounds3> boxes;
        boxes.reserve(faces.size());
        for (int f : faces) {
            const scene::MeshFace& mf = mesh.faces[static_cast<size_t>(f)];
            Face face{mf.v, mf.n, mf.uv, mf.material, f};
            Bounds3 b;
            for (const std::vector<Vec3>& step : positions_)
                for (int k = 0; k < 3; ++k) b.extend(step[static_cast<size_t>(mf.v[k])]);
            // Interpolated corners round by a few ulps past the steps' box.
            for (int a = 0; a < 3; ++a) {
                const double pad = gamma(4) * std::max(std::fabs(b.lo[a]), std::fabs(b.hi[a]));
                b.lo[a] -= pad;
                b.hi[a] += pad;
            }
            bounds_.extend(b);
            faces_.push_back(face);
            boxes.push_back(b);
        }
        bvh_ = Bvh(boxes, 4, 1);
        if (!mesh.attributes.empty() && mesh.corners.size() == mesh.faces.size()) attr_mesh_ = &mesh;
        // Normals per step only where every step has them (the importer writes all or none).
        if (normals_.size() != positions_.size()) normals_.clear();
    }

    Bounds3 bounds() const override { return bounds_; }
    bool writes_whole_hit() const override { return true; }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        const RayShear shear(ray);
        const Lerp at = lerp_at(ray.time);
        int best = -1;
        TriangleHit best_hit{};
        double t_max = tmax;
        bvh_.traverse(ray, t_max, [&](int i, double& limit) {
            Vec3 p[3];
            corners(faces_[static_cast<size_t>(i)], at, p);
            TriangleHit th;
            if (intersect_triangle(shear, p[0], p[1], p[2], limit, &th)) {
                best = i;
                best_hit = th;
                limit = th.t;
            }
            return false;
        });
        if (best < 0) return false;
        fill(faces_[static_cast<size_t>(best)], at, best_hit, hit);
        return true;
    }

    bool occludes(const Ray& ray, double tmax) const override {
        const RayShear shear(ray);
        const Lerp at = lerp_at(ray.time);
        double t_max = tmax;
        return bvh_.traverse(ray, t_max, [&](int i, double& limit) {
            Vec3 p[3];
            corners(faces_[static_cast<size_t>(i)], at, p);
            TriangleHit th;
            return intersect_triangle(shear, p[0], p[1], p[2], limit, &th);
        });
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        const RayShear shear(ray);
        const Lerp at = lerp_at(ray.time);
        double t_max = tmax;
        bvh_.traverse(ray, t_max, [&](int i, double& limit) {
            const Face& f = faces_[static_cast<size_t>(i)];
            Vec3 p[3];
            corners(f, at, p);
            TriangleHit th;
            if (intersect_triangle(shear, p[0], p[1], p[2], limit, &th))
                fill(f, at, th, &hits->emplace_back());
            return false;
        });
    }

    // Blender's meshes, the only deforming ones, have no inside_vector: never inside.
    bool inside(const Vec3&) const override { return false; }

    bool attribute(std::string_view name, Want want, int face, double b1, double b2, Vec3* value,
                   double* alpha) const override {
        return attr_mesh_ && mesh_attribute(*attr_mesh_, name, want, face, b1, b2, value, alpha);
    }
    bool corner_normal(int face, double b1, double b2, Vec3* n) const override {
        return attr_mesh_ && mesh_corner_normal(*attr_mesh_, face, b1, b2, n);
    }

private:
    struct Face {
        std::array<int, 3> v, n, uv;
        int material;
        int scene_face;
    };
    // The two steps about a time and the weight of the later one (Cycles'
    // motion_triangle_verts_for_step: step = min(floor(t (n - 1)), n - 2)).
    struct Lerp {
        size_t step;
        double f;
    };
    Lerp lerp_at(double time) const {
        const double last = static_cast<double>(positions_.size() - 1);
        const double s = std::clamp(time, 0.0, 1.0) * last;
        const size_t step = std::min(static_cast<size_t>(s), positions_.size() - 2);
        return {step, s - static_cast<double>(step)};
    }
    static Vec3 mix(const std::vector<Vec3>& a, const std::vector<Vec3>& b, int i, double f) {
        const Vec3& x = a[static_cast<size_t>(i)];
        return x + (b[static_cast<size_t>(i)] - x) * f;
    }
    void corners(const Face& face, const Lerp& at, Vec3 p[3]) const {
        const std::vector<Vec3>&a = positions_[at.step], &b = positions_[at.step + 1];
        for (int k = 0; k < 3; ++k) p[k] = mix(a, b, face.v[static_cast<size_t>(k)], at.f);
    }

    void fill(const Face& face, const Lerp& at, const TriangleHit& th, LocalHit* h) const {
        *h = LocalHit();
        Vec3 p[3];
        corners(face, at, p);
        h->t = th.t;
        h->p = triangle_point(p[0], p[1], p[2], th.b, &h->p_error);
        h->ng = normalize(cross(p[1] - p[0], p[2] - p[0]));
        h->n = h->ng;
        if (!normals_.empty() && face.n[0] >= 0 && face.n[1] >= 0 && face.n[2] >= 0) {
            const std::vector<Vec3>&a = normals_[at.step], &b = normals_[at.step + 1];
            h->n = interpolated_normal(mix(a, b, face.n[0], at.f), mix(a, b, face.n[1], at.f),
                                       mix(a, b, face.n[2], at.f), th.b, h->ng);
        }
        h->has_uv = !uvs_.empty() && face.uv[0] >= 0 && face.uv[1] >= 0 && face.uv[2] >= 0;
        if (h->has_uv)
            interpolate_uv(p[0], p[1], p[2], uvs_[static_cast<size_t>(face.uv[0])],
                           uvs_[static_cast<size_t>(face.uv[1])],
                           uvs_[static_cast<size_t>(face.uv[2])], th.b, h);
        h->material = face.material;
        if (attr_mesh_)
            h->attributes = {this, face.scene_face, static_cast<float>(th.b[1]),
                             static_cast<float>(th.b[2])};
    }

    std::vector<std::vector<Vec3>> positions_;  // per step, per vertex
    std::vector<std::vector<Vec3>> normals_;    // per step, per corner; empty: flat
    std::vector<Vec2> uvs_;
    std::vector<Face> faces_;
    Bvh bvh_;
    Bounds3 bounds_;
    const scene::Mesh* attr_mesh_ = nullptr;
};

}  // namespace

std::unique_ptr<Primitive> make_motion_mesh(const scene::Mesh& mesh, const std::vector<int>& faces) {
    for (const std::vector<Vec3>& step : mesh.motion_positions)
        if (step.size() != mesh.positions.size()) return nullptr;
    if (mesh.motion_positions.size() < 2 || faces.empty()) return nullptr;
    return std::make_unique<MotionMeshPrim>(mesh, faces);
}

}  // namespace glint::render
