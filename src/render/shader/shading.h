// Where a path meets a surface with a node graph: the shading point's globals (ShaderGlobals)
// from the hit, its object and the camera, and the compiled programs of the scene's graphs.
#pragma once

#include <memory>
#include <vector>

#include "core/log.h"
#include "render/ray.h"
#include "render/shader/program.h"
#include "scene/scene.h"

namespace glint::render {
class TextureCache;
class VdbGrids;
}

namespace glint::render::shader {

// What a ray knows when it reaches a surface (the Light Path node's view of it).
struct RayState {
    bool camera = true, shadow = false, diffuse = false, glossy = false, singular = false,
         reflection = false, transmission = false;
    double length = 0;      // from the last scattering (or the camera)
    double travelled = 0;   // from the camera, along the whole path (bump's footprint)
    int depth = 0, diffuse_depth = 0, glossy_depth = 0, transparent_depth = 0,
        transmission_depth = 0;
};

class GraphShading {
public:
    // Compiles every graph of `scene` (materials, world); warnings go to `diag`.
    GraphShading(const scene::Scene& scene, int width, int height, TextureCache* textures,
                 Diagnostics& diag);
    ~GraphShading();

    bool any() const { return !programs_.empty(); }
    // The program of material `m`, null when it has none.
    const ShaderProgram* material(int m) const {
        return m >= 0 && static_cast<size_t>(m) < by_material_.size() ? by_material_[m] : nullptr;
    }
    const ShaderProgram* world() const { return world_; }

    // The globals at `hit` seen along the unit `dir`.
    ShaderGlobals globals(const Hit& hit, const Vec3& dir, const RayState& ray) const;
    // Their N: the shading normal turned towards the viewer (Cycles' sd->N).
    static float3 normal(const Hit& hit, const Vec3& dir);
    // The world's globals for a ray leaving along `dir`.
    ShaderGlobals world_globals(const Vec3& dir, const RayState& ray) const;
    // A volume shader's globals at `p` inside `object` (-1: the world's volume), on a ray
    // along the unit `dir` (Cycles' shader_setup_from_volume: N and Ng face back along it).
    ShaderGlobals volume_globals(int object, const Vec3& p, const Vec3& dir) const;
    // A Volume object's grids (null for other objects).
    const VdbGrids* grids(int object) const;
    // What Cycles scales a volume's coefficients by in `object` (object_volume_density): for a
    // Volume object whose space is its own, 1 / |M normalize(1, 1, 1)|, so the density stays
    // with the object as it is scaled; 1 for everything else.
    double volume_density(int object) const {
        return object >= 0 && static_cast<size_t>(object) < objects_.size()
                   ? objects_[static_cast<size_t>(object)].volume_density : 1.0;
    }

private:
    struct ObjectInfo {
        float o2w[3][4];
        float w2o[3][4];
        float3 location, gen_location, gen_scale{0.5f, 0.5f, 0.5f}, color{1, 1, 1};
        float pass_index = 0, random = 0;
        double volume_density = 1;
    };
    void camera_coords(const Vec3& p, ShaderGlobals* sg) const;
    // The object's part of the globals (transforms, Object and Generated coordinates, Object
    // Info) at sg->P; world coordinates for none (-1).
    void object_globals(int object, ShaderGlobals* sg) const;

    std::vector<std::unique_ptr<ShaderProgram>> programs_;
    std::vector<const ShaderProgram*> by_material_;
    const ShaderProgram* world_ = nullptr;
    std::vector<ObjectInfo> objects_;
    std::vector<std::unique_ptr<VdbGrids>> grids_;  // per object; only Volume objects have any
    // The camera, for Camera Data, the Camera and Window coordinates and bump's footprint.
    Vec3 cam_location_, cam_right_, cam_up_, cam_forward_, cam_direction_;
    double cam_len_right_ = 1, cam_len_up_ = 1;
    bool cam_ortho_ = false;
    double pixel_angle_ = 0.001;  // the pixel's width at unit distance
    double ortho_pixel_ = 0;      // an orthographic camera's pixel width
    float w2c_[3][4] = {}, c2w_[3][4] = {};  // Cycles' camera space (ShaderGlobals)
};

}  // namespace glint::render::shader
