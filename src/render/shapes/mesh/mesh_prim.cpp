// mesh / mesh2 (POV-Ray 3.7 manual 2.4.2.2-3) and OBJ meshes: the faces of a scene::Mesh
// behind their own BVH in object space.
#include "render/shapes/mesh/mesh_prim.h"

#include <array>
#include <cstring>
#include <cmath>
#include <optional>
#include <string>

#include "render/accel/bvh.h"
#include "render/accel/huge_pages.h"
#include "render/shapes/object_node.h"
#include "render/accel/wide_bvh.h"
#include "render/shapes/mesh/mesh_kernels.h"
#include "render/shapes/mesh/mesh_shading.h"
#include "render/shapes/mesh/motion_mesh.h"
#include "render/shapes/mesh/triangle.h"

namespace glint::render {
namespace {

// Memory per triangle (bench/traversal_bench.cpp measures it): 36 bytes of float vertices and
// 4 of face index in the kernels' leaf layout (mesh_kernels.h), and the eight-wide BVH's share;
// normal, uv and material indices only for meshes that have them.
//
// The vertices are floats relative to the centre of the mesh's box (POV-Ray keeps mesh vertices
// in single precision too, mesh.h): a triangle's corners are origin + float offset exactly, the
// ray is moved into that frame once, and the watertight test runs in double on the widened
// floats. Precision follows the mesh's size, not its distance from the scene's origin, so a
// mesh 1e5 units away keeps the detail of one at the origin.
class MeshPrim final : public Primitive, public AttributeSource {
public:
    MeshPrim(const scene::Mesh& mesh, const std::vector<int>& faces, const Transform* baked) {
        if (baked) {
            baked_ = true;
            const auto& m = baked->matrix().m;
            for (int a = 0; a < 3; ++a) flip_[a] = m[a][a] < 0;
        }
        Bounds3 all;
        for (int f : faces)
            for (int k = 0; k < 3; ++k) all.extend(mesh.positions[mesh.faces[f].v[k]]);
        origin_ = all.centroid();
        // Float corners; a face that rounding makes degenerate is dropped like a zero-area one.
        std::vector<std::array<Vec3, 3>> local;
        std::vector<int> kept;
        local.reserve(faces.size());
        kept.reserve(faces.size());
        for (int f : faces) {
            std::array<Vec3, 3> c;
            for (int k = 0; k < 3; ++k) {
                const Vec3 d = mesh.positions[mesh.faces[f].v[k]] - origin_;
                c[k] = {static_cast<float>(d.x), static_cast<float>(d.y), static_cast<float>(d.z)};
            }
            const Vec3 n = cross(c[1] - c[0], c[2] - c[0]);
            if (!is_finite(n) || !(length_squared(n) > 0)) {
                ++dropped_;
                continue;
            }
            local.push_back(c);
            kept.push_back(f);
        }
        std::vector<Bounds3> boxes(local.size());
        for (size_t i = 0; i < local.size(); ++i)
            for (int k = 0; k < 3; ++k) boxes[i].extend(local[i][k]);
        // Leaves of up to 16, tested four at a time, a node visit priced as one of those
        // tests. (The four-wide tree paid for larger leaves on large meshes, a visit priced
        // as three tests; in the eight-wide tree, with a third fewer node visits, a price of
        // one is the faster on every size: traversal_bench's 1M-triangle mesh 0.91 of the
        // time on incoherent closest and any-hit rays, 4 alternating pairs, in 54 bytes a
        // triangle instead of 48; 13% fewer instructions on a 10k mesh in cache.) The
        // eight-wide tree is then cut from it by kMeshCollapse's prices.
        const Bvh bvh(boxes, 4, 4);
        bounds_ = bvh.bounds();
        // Faces in leaf order, each leaf's corners by component (the kernels' layout).
        const std::vector<int>& order = bvh.order();
        const size_t n = order.size();
        tris_.assign(10 * n + 4, 0.0f);
        auto lay_out_leaf = [&](int first, int count) {
            float* leaf = tris_.data() + 10 * static_cast<size_t>(first);
            for (int j = 0; j < count; ++j) {
                for (int v = 0; v < 3; ++v)
                    for (int a = 0; a < 3; ++a)
                        leaf[(3 * v + a) * count + j] =
                            static_cast<float>(local[order[first + j]][v][a]);
                const int32_t face = kept[order[first + j]];
                std::memcpy(leaf + 9 * count + j, &face, sizeof face);
            }
        };
        if (bvh.single_leaf()) {
            lay_out_leaf(0, static_cast<int>(n));
        } else {
            wide_ = WideBvh(bvh, kMeshCollapse);
            wide_.for_each_leaf(lay_out_leaf);
        }
        bool has_normals = false, has_uvs = false, has_material = false;
        std::vector<int> face(n);  // the scene face at each leaf position
        for (size_t i = 0; i < n; ++i) {
            face[i] = kept[order[i]];
            const scene::MeshFace& f = mesh.faces[face[i]];
            has_normals = has_normals || f.n[0] >= 0 || f.n[1] >= 0 || f.n[2] >= 0;
            has_uvs = has_uvs || f.uv[0] >= 0 || f.uv[1] >= 0 || f.uv[2] >= 0;
            has_material = has_material || f.material >= 0;
        }
        if (has_normals) {
            normals_ = mesh.normals;
            nidx_.resize(n);
            for (size_t i = 0; i < n; ++i) nidx_[i] = mesh.faces[face[i]].n;
        }
        if (has_uvs) {
            uvs_ = mesh.uvs;
            uvidx_.resize(n);
            for (size_t i = 0; i < n; ++i) uvidx_[i] = mesh.faces[face[i]].uv;
        }
        if (has_material) {
            material_.resize(n);
            for (size_t i = 0; i < n; ++i) material_[i] = mesh.faces[face[i]].material;
        }
        // Named attributes stay in the scene's mesh (alive while the scene renders); a hit
        // records its scene face.
        if (!mesh.attributes.empty() && mesh.corners.size() == mesh.faces.size()) {
            attr_mesh_ = &mesh;
            scene_face_ = face;
        }
        view_.nodes = wide_.nodes().empty() ? nullptr : wide_.nodes().data();
        view_.tris = tris_.data();
        view_.count = static_cast<int>(n);
        view_.reach = wide_.reach();
        if (mesh.has_inside_vector && length_squared(mesh.inside_vector) > 0)
            inside_dir_ = mesh.inside_vector;
    }

    bool empty() const { return view_.count == 0; }
    std::optional<MeshQuery> query() const {
        if (baked_) return std::nullopt;
        return MeshQuery{&view_, origin_};
    }
    int dropped() const { return dropped_; }

    // The local box about the origin, conservatively in the object (baked: parent) space.
    Bounds3 bounds() const override {
        Bounds3 b;
        for (int a = 0; a < 3; ++a) {
            b.lo[a] = next_down(origin_[a] + bounds_.lo[a]);
            b.hi[a] = next_up(origin_[a] + bounds_.hi[a]);
            if (flip_[a]) {
                const double lo = b.lo[a];
                b.lo[a] = -b.hi[a];
                b.hi[a] = -lo;
            }
        }
        return b;
    }
    bool writes_whole_hit() const override { return true; }

    bool intersect(const Ray& parent_ray, double tmax, LocalHit* hit) const override {
        MeshHit mh;
        if (!kernels_.closest(view_, to_local(parent_ray), tmax, &mh)) return false;
        fill(mh, hit);
        return true;
    }

    bool occludes(const Ray& parent_ray, double tmax) const override {
        return kernels_.any(view_, to_local(parent_ray), tmax);
    }

    void intersect_all(const Ray& parent_ray, double tmax, HitList* hits) const override {
        struct Ctx {
            const MeshPrim* self;
            HitList* hits;
        } ctx{this, hits};
        kernels_.all(view_, to_local(parent_ray), tmax, [](void* c, const MeshHit& mh) {
            auto* x = static_cast<Ctx*>(c);
            x->self->fill(mh, &x->hits->emplace_back());
        }, &ctx);
    }

    // POV-Ray (mesh.cpp, Mesh::Inside): a point is inside when a ray from it along
    // inside_vector crosses the surface an odd number of times. Without one, never inside.
    bool inside(const Vec3& parent_p) const override {
        if (!inside_dir_) return false;
        const Ray ray{mirrored(parent_p) - origin_, *inside_dir_, kInfinity};
        int crossings = 0;
        kernels_.all(view_, ray, kInfinity,
                     [](void* c, const MeshHit&) { ++*static_cast<int*>(c); }, &crossings);
        return crossings % 2 == 1;
    }

private:
    // Baked (a pure mirror, bake_exact): the ray in object space is the parent-space ray with
    // the mirrored components negated, exactly what the transform's matrix computes.
    Vec3 mirrored(Vec3 v) const {
        if (!baked_) return v;  // the usual case, one branch instead of three a vector
        for (int a = 0; a < 3; ++a)
            if (flip_[a]) v[a] = -v[a];
        return v;
    }
    // Into the frame of the float vertices: mirrored if baked, then relative to origin_.
    Ray to_local(const Ray& r) const {
        return {mirrored(r.origin) - origin_, mirrored(r.dir), r.tmax};
    }

    // Writes all of *h (writes_whole_hit), for a kernel hit.
    // Each field is written once, with no *h = LocalHit() first (59 of the 225 instructions
    // a hit cost): LocalHit's size is pinned below so that a new field is not left out.
    void fill(const MeshHit& mh, LocalHit* h) const {
        static_assert(sizeof(void*) != 8 || sizeof(LocalHit) == 240,
                      "a field was added to LocalHit: fill() must set it");
        h->uv = Vec2();
        h->has_uv = false;
        h->uv_source = nullptr;
        h->uv_point = Vec3();
        h->dpdu = Vec3();
        h->dpdv = Vec3();
        h->flags = 0;
        if (attr_mesh_) {
            h->attributes = {this, scene_face_[static_cast<size_t>(mh.index)],
                             static_cast<float>(mh.th.b[1]), static_cast<float>(mh.th.b[2])};
        } else {
            h->attributes = AttributePoint();
        }
        const size_t at = static_cast<size_t>(mh.index);
        const TriangleHit& th = mh.th;
        const Vec3 &p0 = mh.p[0], &p1 = mh.p[1], &p2 = mh.p[2];
        h->t = th.t;
        // The point in the local frame with its bound, then moved back: one more rounding.
        h->p = triangle_point(p0, p1, p2, th.b, &h->p_error) + origin_;
        h->p_error += rounding_error(h->p, 1);
        h->ng = normalize(cross(p1 - p0, p2 - p0));
        h->n = h->ng;
        if (!normals_.empty()) {
            const auto& ni = nidx_[at];
            if (ni[0] >= 0 && ni[1] >= 0 && ni[2] >= 0)
                h->n = interpolated_normal(normals_[ni[0]], normals_[ni[1]], normals_[ni[2]],
                                           th.b, h->ng);
        }
        // A face without uv_vectors has uv (0, 0), as POV-Ray gives a mesh without them (and
        // Cycles a mesh without a UV map), not the world x, y of shapes with no uv at all.
        h->has_uv = true;
        if (!uvs_.empty()) {
            const auto& ui = uvidx_[at];
            if (ui[0] >= 0 && ui[1] >= 0 && ui[2] >= 0)
                interpolate_uv(p0, p1, p2, uvs_[ui[0]], uvs_[ui[1]], uvs_[ui[2]], th.b, h);
        }
        h->material = material_.empty() ? -1 : material_[at];
        // Baked: the hit was computed in object space; the mirror takes it out without
        // rounding, so the point keeps its bound.
        if (baked_) {
            h->p = mirrored(h->p);
            h->ng = mirrored(h->ng);
            h->n = mirrored(h->n);
            h->dpdu = mirrored(h->dpdu);
            h->dpdv = mirrored(h->dpdv);
        }
    }

    bool attribute(std::string_view name, Want want, int face, double b1, double b2, Vec3* value,
                   double* alpha) const override {
        return attr_mesh_ && mesh_attribute(*attr_mesh_, name, want, face, b1, b2, value, alpha);
    }
    bool corner_normal(int face, double b1, double b2, Vec3* n) const override {
        return attr_mesh_ && mesh_corner_normal(*attr_mesh_, face, b1, b2, n);
    }

    using Index3 = std::array<int, 3>;
    Vec3 origin_;                // the float vertices are offsets from here
    Bounds3 bounds_;             // of the float vertices, about origin_
    // Corners in leaf order, the kernels' layout (mesh_kernels.h).
    std::vector<float, HugePageAllocator<float>> tris_;
    WideBvh wide_;               // empty: the mesh is one leaf
    MeshView view_;
    const MeshKernels& kernels_ = mesh_kernels();
    std::vector<Vec3> normals_;  // empty: flat
    std::vector<Index3> nidx_;   // normal indices, in leaf order
    std::vector<Vec2> uvs_;      // empty: no uvs
    std::vector<Index3> uvidx_;  // uv indices, in leaf order
    std::vector<int> material_;  // empty: every face -1
    const scene::Mesh* attr_mesh_ = nullptr;  // set when the mesh has named attributes
    std::vector<int> scene_face_;              // then: the scene face at each leaf position
    std::optional<Vec3> inside_dir_;  // object space
    int dropped_ = 0;                 // faces that became degenerate as floats
    bool baked_ = false;
    bool flip_[3] = {false, false, false};  // baked: the axes the mirror negates
};

}  // namespace

bool mesh_attribute(const scene::Mesh& mesh, std::string_view name, AttributeSource::Want want,
                    int face, double b1, double b2, Vec3* value, double* alpha) {
    if (face < 0 || static_cast<size_t>(face) >= mesh.corners.size()) return false;
    using Kind = scene::MeshAttribute::Kind;
    using Want = AttributeSource::Want;
    const scene::MeshAttribute* found = nullptr;
    for (const scene::MeshAttribute& a : mesh.attributes) {
        if ((want == Want::UV && a.kind != Kind::UV) ||
            (want == Want::Color && a.kind != Kind::Color) ||
            ((want == Want::Tangent) != (a.kind == Kind::Tangent)))
            continue;
        if (name.empty() ? a.active_render : a.name == name) {
            found = &a;
            break;
        }
    }
    if (!found) return false;
    std::array<int, 3> c = mesh.corners[static_cast<size_t>(face)];
    if (found->per_triangle_corner) {
        if (found->values.size() < 3 * mesh.faces.size()) return false;
        c = {3 * face, 3 * face + 1, 3 * face + 2};
    }
    const double b0 = 1 - b1 - b2;
    *value = found->values[c[0]] * b0 + found->values[c[1]] * b1 + found->values[c[2]] * b2;
    *alpha = found->alpha.empty() ? 1.0
                                  : found->alpha[c[0]] * b0 + found->alpha[c[1]] * b1 +
                                        found->alpha[c[2]] * b2;
    return true;
}

bool mesh_corner_normal(const scene::Mesh& mesh, int face, double b1, double b2, Vec3* n) {
    if (face < 0 || static_cast<size_t>(face) >= mesh.faces.size()) return false;
    const auto& ni = mesh.faces[static_cast<size_t>(face)].n;
    const int count = static_cast<int>(mesh.normals.size());
    for (int k = 0; k < 3; ++k)
        if (ni[static_cast<size_t>(k)] < 0 || ni[static_cast<size_t>(k)] >= count) return false;
    *n = mesh.normals[static_cast<size_t>(ni[0])] * (1 - b1 - b2) +
         mesh.normals[static_cast<size_t>(ni[1])] * b1 + mesh.normals[static_cast<size_t>(ni[2])] * b2;
    return true;
}

std::optional<MeshQuery> mesh_query(const Primitive& prim) {
    const auto* mesh = dynamic_cast<const MeshPrim*>(&prim);
    return mesh ? mesh->query() : std::nullopt;
}

bool bake_exact(const Transform& xf) {
    if (xf.is_identity()) return false;
    const auto& m = xf.matrix().m;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double v = m[i][j];
            bool ok = i == j ? (v == 1 || (v == -1 && i < 3)) : v == 0;
            if (!ok) return false;
        }
    return xf.inverse_matrix() == xf.matrix();
}

namespace {

// How a warning about `mesh` starts: its OBJ object's name where it has one.
std::string mesh_label(const scene::Mesh& mesh) {
    return mesh.name.empty() ? std::string() : "object '" + mesh.name + "': ";
}

// The faces of `mesh` a ray can hit: indices in range, finite, non-zero area. The others are
// counted in warnings at the mesh's location.
std::vector<int> usable_faces(const scene::Mesh& mesh, Diagnostics& diag) {
    std::vector<int> usable;
    int degenerate = 0, bad_index = 0;
    int np = static_cast<int>(mesh.positions.size());
    int nn = static_cast<int>(mesh.normals.size());
    int nuv = static_cast<int>(mesh.uvs.size());
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
        const scene::MeshFace& face = mesh.faces[f];
        bool ok = true;
        for (int k = 0; k < 3; ++k) {
            ok = ok && face.v[k] >= 0 && face.v[k] < np && face.n[k] < nn && face.uv[k] < nuv;
        }
        if (!ok) {
            ++bad_index;
            continue;
        }
        const Vec3 &p0 = mesh.positions[face.v[0]], &p1 = mesh.positions[face.v[1]],
                   &p2 = mesh.positions[face.v[2]];
        Vec3 c = cross(p1 - p0, p2 - p0);
        // A vertex beyond 1e15 (VALIDATION.md case 7's 1e30) is corrupt input, not geometry:
        // there a double cannot resolve 1/8 of a unit, and the triangle would cut the scene
        // as a sliver of unbounded size.
        constexpr double kMaxCoordinate = 1e15;
        auto sane = [&](const Vec3& p) {
            return std::fabs(p.x) <= kMaxCoordinate && std::fabs(p.y) <= kMaxCoordinate &&
                   std::fabs(p.z) <= kMaxCoordinate;
        };
        if (!sane(p0) || !sane(p1) || !sane(p2) || !is_finite(c) ||
            !(length_squared(c) > 0)) {
            ++degenerate;
            continue;
        }
        usable.push_back(static_cast<int>(f));
    }
    const std::string who = mesh_label(mesh);
    if (degenerate > 0)
        diag.warning(mesh.loc, who + std::to_string(degenerate) +
                                   " degenerate mesh triangle(s) (zero area, or vertices not "
                                   "finite or beyond 1e15) skipped");
    if (bad_index > 0)
        diag.warning(mesh.loc, who + std::to_string(bad_index) +
                                   " mesh triangle(s) with invalid indices skipped");
    return usable;
}

std::unique_ptr<Primitive> make_prim(const scene::Mesh& mesh, const std::vector<int>& usable,
                                     Diagnostics& diag, const Transform* baked) {
    if (usable.empty()) return nullptr;
    if (!mesh.motion_positions.empty()) return make_motion_mesh(mesh, usable);
    auto prim = std::make_unique<MeshPrim>(mesh, usable, baked);
    if (prim->dropped() > 0)
        diag.warning(mesh.loc, mesh_label(mesh) +
                                   std::to_string(prim->dropped()) +
                                   " mesh triangle(s) too small for single precision skipped");
    if (prim->empty()) return nullptr;
    return prim;
}

}  // namespace

std::unique_ptr<Primitive> make_mesh(const scene::Mesh& mesh, Diagnostics& diag,
                                     const Transform* baked) {
    return make_prim(mesh, usable_faces(mesh, diag), diag, baked);
}

std::unique_ptr<Primitive> make_merged_mesh(const std::vector<MeshPart>& parts,
                                            Diagnostics& diag, const Transform* baked) {
    scene::Mesh all;
    if (!parts.empty()) all.loc = parts[0].mesh->loc;
    std::vector<int> usable;
    for (const MeshPart& part : parts) {
        const scene::Mesh& m = *part.mesh;
        const int v0 = static_cast<int>(all.positions.size()),
                  n0 = static_cast<int>(all.normals.size()),
                  uv0 = static_cast<int>(all.uvs.size());
        for (int f : usable_faces(m, diag)) {
            scene::MeshFace face = m.faces[f];
            for (int k = 0; k < 3; ++k) {
                face.v[k] += v0;
                if (face.n[k] >= 0) face.n[k] += n0;
                if (face.uv[k] >= 0) face.uv[k] += uv0;
            }
            if (face.material < 0) face.material = part.material;
            usable.push_back(static_cast<int>(all.faces.size()));
            all.faces.push_back(face);
        }
        all.positions.insert(all.positions.end(), m.positions.begin(), m.positions.end());
        all.normals.insert(all.normals.end(), m.normals.begin(), m.normals.end());
        all.uvs.insert(all.uvs.end(), m.uvs.begin(), m.uvs.end());
    }
    return make_prim(all, usable, diag, baked);
}

}  // namespace glint::render
