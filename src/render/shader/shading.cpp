#include "render/shader/shading.h"

#include "render/textures/vdb_grids.h"

#include <algorithm>
#include <cmath>

namespace glint::render::shader {

namespace {

void to_rows(const Matrix4& m, float out[3][4]) {
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 4; ++k) out[i][k] = static_cast<float>(m.m[i][k]);
}

float3 xform_vector(const float m[3][4], float3 v) {
    float3 r;
    for (int i = 0; i < 3; ++i) r[i] = m[i][0] * v.x + m[i][1] * v.y + m[i][2] * v.z;
    return r;
}

float3 xform_point(const float m[3][4], float3 v) {
    float3 r = xform_vector(m, v);
    for (int i = 0; i < 3; ++i) r[i] += m[i][3];
    return r;
}

}  // namespace

GraphShading::GraphShading(const scene::Scene& scene, int width, int height,
                           TextureCache* textures, Diagnostics& diag) {
    // One program per graph, shared by the materials that name it.
    std::vector<const ShaderProgram*> by_graph(scene.shader_graphs.size(), nullptr);
    auto program = [&](int g) -> const ShaderProgram* {
        if (g < 0 || static_cast<size_t>(g) >= scene.shader_graphs.size()) return nullptr;
        if (!by_graph[g]) {
            programs_.push_back(ShaderProgram::compile(scene.shader_graphs[g], textures, diag));
            by_graph[g] = programs_.back().get();
        }
        return by_graph[g];
    };
    by_material_.reserve(scene.materials.size());
    for (const scene::Material& m : scene.materials) by_material_.push_back(program(m.graph));
    world_ = program(scene.world_graph);
    if (programs_.empty()) return;

    objects_.resize(scene.objects.size());
    grids_.resize(scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const scene::Object& o = scene.objects[i];
        ObjectInfo& info = objects_[i];
        if (o.volume_file) {
            grids_[i] = std::make_unique<VdbGrids>(o.volume_file->path, o.transform, diag, o.loc);
            if (o.volume_file->object_space) {
                const double l = length(o.transform.vector(normalize(Vec3(1, 1, 1))));
                if (l > 0) info.volume_density = 1.0 / l;
            }
        }
        to_rows(o.transform.matrix(), info.o2w);
        to_rows(o.transform.inverse_matrix(), info.w2o);
        info.location = float3(o.transform.point(Vec3(0, 0, 0)));
        info.color = float3(static_cast<float>(o.info_color.r), static_cast<float>(o.info_color.g),
                            static_cast<float>(o.info_color.b));
        info.pass_index = static_cast<float>(o.pass_index);
        info.random = static_cast<float>(o.random);
        if (const auto* ref = std::get_if<scene::MeshRef>(&o.shape);
            ref && ref->mesh >= 0 && static_cast<size_t>(ref->mesh) < scene.meshes.size()) {
            const scene::Mesh& mesh = scene.meshes[ref->mesh];
            Vec3 loc = mesh.texspace_location, size = mesh.texspace_size;
            if (!mesh.has_texspace && !mesh.positions.empty()) {
                Vec3 lo = mesh.positions[0], hi = lo;
                for (const Vec3& p : mesh.positions) lo = min(lo, p), hi = max(hi, p);
                loc = (lo + hi) * 0.5;
                size = (hi - lo) * 0.5;
                for (int k = 0; k < 3; ++k)
                    if (!(size[k] > 0)) size[k] = 1;
            }
            info.gen_location = float3(loc);
            for (int k = 0; k < 3; ++k) info.gen_scale[k] = static_cast<float>(0.5 / size[k]);
        }
    }

    const scene::Camera& c = scene.camera;
    cam_location_ = c.location;
    cam_len_right_ = length(c.right);
    cam_len_up_ = length(c.up);
    cam_right_ = cam_len_right_ > 0 ? c.right / cam_len_right_ : Vec3(1, 0, 0);
    cam_up_ = cam_len_up_ > 0 ? c.up / cam_len_up_ : Vec3(0, 1, 0);
    cam_forward_ = normalize(cross(cam_up_, cam_right_));
    if (dot(cam_forward_, c.direction) < 0) cam_forward_ = -cam_forward_;
    cam_direction_ = c.direction;
    cam_ortho_ = c.kind == scene::CameraKind::Orthographic;
    const double along = std::max(dot(c.direction, cam_forward_), 1e-9);
    pixel_angle_ = cam_len_right_ / std::max(width, 1) / along;
    const Vec3 axes[3] = {cam_right_, cam_up_, cam_forward_};
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) {
            w2c_[i][k] = static_cast<float>(axes[i][k]);
            c2w_[k][i] = static_cast<float>(axes[i][k]);
        }
        w2c_[i][3] = static_cast<float>(-dot(axes[i], cam_location_));
        c2w_[i][3] = static_cast<float>(cam_location_[i]);
    }
    if (cam_ortho_) {
        pixel_angle_ = 0;
        ortho_pixel_ = cam_len_right_ / std::max(width, 1);
    }
    (void)height;
}

void GraphShading::camera_coords(const Vec3& p, ShaderGlobals* sg) const {
    const Vec3 d = p - cam_location_;
    sg->camera_position = float3(static_cast<float>(dot(d, cam_right_)),
                                 static_cast<float>(dot(d, cam_up_)),
                                 static_cast<float>(dot(d, cam_forward_)));
    sg->view_distance = static_cast<float>(length(d));
    // The image position: where the camera's ray through p crosses the image.
    double sx = 0, sy = 0;
    if (cam_ortho_) {
        sx = dot(d, cam_right_) / cam_len_right_;
        sy = dot(d, cam_up_) / cam_len_up_;
    } else {
        const double z = dot(d, cam_forward_);
        if (z != 0) {
            const Vec3 on = d * (dot(cam_direction_, cam_forward_) / z) - cam_direction_;
            sx = dot(on, cam_right_) / cam_len_right_;
            sy = dot(on, cam_up_) / cam_len_up_;
        }
    }
    sg->window = float3(static_cast<float>(sx + 0.5), static_cast<float>(sy + 0.5), 0);
}

void GraphShading::object_globals(int object, ShaderGlobals* sg) const {
    if (object >= 0 && static_cast<size_t>(object) < objects_.size()) {
        const ObjectInfo& o = objects_[static_cast<size_t>(object)];
        std::copy(&o.o2w[0][0], &o.o2w[0][0] + 12, &sg->object_to_world[0][0]);
        std::copy(&o.w2o[0][0], &o.w2o[0][0] + 12, &sg->world_to_object[0][0]);
        sg->object = xform_point(o.w2o, sg->P);
        sg->generated = (sg->object - o.gen_location) * o.gen_scale + float3(0.5f);
        sg->generated_scale = o.gen_scale;
        sg->object_location = o.location;
        sg->object_color = o.color;
        sg->object_pass_index = o.pass_index;
        sg->object_random = o.random;
    } else {
        sg->object = sg->P;
        sg->generated = sg->P;
    }
}

GraphShading::~GraphShading() = default;

const VdbGrids* GraphShading::grids(int object) const {
    return object >= 0 && static_cast<size_t>(object) < grids_.size()
               ? grids_[static_cast<size_t>(object)].get() : nullptr;
}

ShaderGlobals GraphShading::volume_globals(int object, const Vec3& p, const Vec3& dir) const {
    ShaderGlobals sg;
    sg.P = float3(p);
    sg.grids = grids(object);
    sg.I = sg.N = sg.Ng = float3(-dir);
    object_globals(object, &sg);
    camera_coords(p, &sg);
    std::copy(&w2c_[0][0], &w2c_[0][0] + 12, &sg.world_to_camera[0][0]);
    std::copy(&c2w_[0][0], &c2w_[0][0] + 12, &sg.camera_to_world[0][0]);
    sg.camera_ray = false;
    return sg;
}

float3 GraphShading::normal(const Hit& hit, const Vec3& dir) {
    return float3(dot(hit.ng, dir) > 0 ? -hit.n : hit.n);
}

ShaderGlobals GraphShading::globals(const Hit& hit, const Vec3& dir,
                                    const RayState& ray) const {
    ShaderGlobals sg;
    sg.P = float3(hit.p);
    // Cycles turns N and Ng towards the viewer and says when it did.
    sg.backfacing = dot(hit.ng, dir) > 0;
    const double s = sg.backfacing ? -1 : 1;
    sg.N = normal(hit, dir);
    sg.Ng = float3(hit.ng * s);
    sg.I = float3(-dir);
    sg.uv = hit.has_uv ? float3(static_cast<float>(hit.uv.x), static_cast<float>(hit.uv.y), 0)
                       : float3();
    sg.dPdu = float3(hit.dpdu);
    sg.attributes = hit.attributes;
    sg.dPdv = float3(hit.dpdv);
    object_globals(hit.object, &sg);
    // Cycles' tangent (Geometry's Tangent, and the default of Anisotropic and Principled):
    // around the Z axis of the texture space, through the normal transform, then made
    // perpendicular to N.
    {
        const float3 g = sg.generated - float3(0.5f);
        float3 t(-g.y, g.x, 0);
        if (hit.object >= 0 && static_cast<size_t>(hit.object) < objects_.size()) {
            const ObjectInfo& o = objects_[hit.object];
            float3 w;
            for (int i = 0; i < 3; ++i)
                w[i] = o.w2o[0][i] * t.x + o.w2o[1][i] * t.y + o.w2o[2][i] * t.z;
            t = w;
        }
        sg.tangent = cross(sg.N, safe_normalize(cross(t, sg.N)));
    }
    // The normal map's tangent: the uv direction (MikkTSpace's stand-in), else the above.
    sg.uv_tangent = len(sg.dPdu) > 0 ? safe_normalize(sg.dPdu) : sg.tangent;
    camera_coords(hit.p, &sg);
    std::copy(&w2c_[0][0], &w2c_[0][0] + 12, &sg.world_to_camera[0][0]);
    std::copy(&c2w_[0][0], &c2w_[0][0] + 12, &sg.camera_to_world[0][0]);
    // Bump's steps, as Cycles 3.4 takes them (its compact ray differentials,
    // kernel/util/differential.h: differential_from_compact(Ng, dP)): the pixel's footprint
    // at this distance (an orthographic camera's pixel width), along make_orthonormals(Ng).
    const double footprint =
        std::max(ortho_pixel_ + pixel_angle_ * (ray.travelled + hit.t), 1e-6 * (1 + length(hit.p)));
    const float3 ng = sg.Ng;
    float3 a = ng.x != ng.y || ng.x != ng.z ? float3(ng.z - ng.y, ng.x - ng.z, ng.y - ng.x)
                                            : float3(ng.z - ng.y, ng.x + ng.z, -ng.y - ng.x);
    a = safe_normalize(a);
    const float3 b = cross(ng, a);
    sg.dPdx = a * static_cast<float>(footprint);
    sg.dPdy = b * static_cast<float>(footprint);
    sg.camera_ray = ray.camera;
    sg.shadow_ray = ray.shadow;
    sg.diffuse_ray = ray.diffuse;
    sg.glossy_ray = ray.glossy;
    sg.singular_ray = ray.singular;
    sg.reflection_ray = ray.reflection;
    sg.transmission_ray = ray.transmission;
    sg.ray_length = static_cast<float>(ray.length + hit.t);
    sg.ray_depth = ray.depth;
    sg.diffuse_depth = ray.diffuse_depth;
    sg.glossy_depth = ray.glossy_depth;
    sg.transparent_depth = ray.transparent_depth;
    sg.transmission_depth = ray.transmission_depth;
    return sg;
}

ShaderGlobals GraphShading::world_globals(const Vec3& dir, const RayState& ray) const {
    // Cycles shades the world with P = the direction, and texture coordinates from it.
    ShaderGlobals sg;
    const float3 d(dir);
    sg.P = d;
    sg.N = -d;
    sg.Ng = -d;
    sg.I = -d;
    sg.generated = d;
    sg.object = d;
    sg.camera_ray = ray.camera;
    sg.diffuse_ray = ray.diffuse;
    sg.glossy_ray = ray.glossy;
    sg.singular_ray = ray.singular;
    sg.reflection_ray = ray.reflection;
    sg.transmission_ray = ray.transmission;
    sg.ray_depth = ray.depth;
    sg.ray_length = 3.4e38f;
    camera_coords(cam_location_ + dir, &sg);
    std::copy(&w2c_[0][0], &w2c_[0][0] + 12, &sg.world_to_camera[0][0]);
    std::copy(&c2w_[0][0], &c2w_[0][0] + 12, &sg.camera_to_world[0][0]);
    return sg;
}

}  // namespace glint::render::shader
