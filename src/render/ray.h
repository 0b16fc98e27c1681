// Rays and surface hits: the contract between geometry (shapes, BVH, CSG) and integrators.
#pragma once

#include <cstdint>
#include <string_view>

#include "core/math.h"

namespace glint::render {

// Where a hit's named attributes come from (a mesh's UV maps and colour attributes): looked
// up by the shading of node graphs at the face and barycentric point the hit recorded.
class AttributeSource {
public:
    enum class Want { Any, UV, Color, Tangent };  // Any: a UV map or a colour
    virtual ~AttributeSource() = default;
    // The attribute `name` of kind `want` (an empty name: the active render layer of that
    // kind) at the face's barycentric point (b1, b2 of its second and third corners); false
    // when the mesh has none by that name.
    virtual bool attribute(std::string_view name, Want want, int face, double b1, double b2,
                           Vec3* value, double* alpha) const = 0;
    // The face's corner normals interpolated at the point and not normalized (what Cycles'
    // Normal Map combines with the tangent), in object space; false on a flat face.
    virtual bool corner_normal(int face, double b1, double b2, Vec3* n) const = 0;
};

// A hit's attribute lookup: the source and the point on it.
struct AttributePoint {
    const AttributeSource* source = nullptr;
    int face = -1;
    float b1 = 0, b2 = 0;
};

struct Ray {
    Vec3 origin;
    Vec3 dir;  // not necessarily normalized; t is in units of dir
    double tmax = kInfinity;
    // Motion blur: the shutter time in [0, 1] the ray travels at (the camera ray's, kept by
    // every ray of its path); 0.5 is the frame itself, what scenes without motion see.
    double time = 0.5;
};

// Object flags that integrators consult (POV-Ray object modifiers).
enum ObjectFlags : uint32_t {
    kNoShadow = 1u << 0,
    kNoImage = 1u << 1,
    kNoReflection = 1u << 2,
    kDoubleIlluminate = 1u << 3,
    kNoRadiosity = 1u << 4,
    kNoGlobalLights = 1u << 5,  // scene::Object::no_global_lights
    // scene::Object::hollow of the shape or of a CSG around it: POV-Ray keeps `hollow` with the
    // interior of the shape the ray entered, so a hollow sphere inside a union is hollow.
    kHollow = 1u << 6,
    // The high bits hold scene::Object::light_group + 1 (0: none): the innermost object that
    // has one sets it, where the other flags gather from every level.
    kLightGroupMask = 0xffffff00u,
};
constexpr int kLightGroupShift = 8;

inline uint32_t light_group_flags(int light_group) {
    return light_group >= 0 ? static_cast<uint32_t>(light_group + 1) << kLightGroupShift : 0u;
}
inline int light_group_of(uint32_t flags) {
    return static_cast<int>(flags >> kLightGroupShift) - 1;
}
// An enclosing object's flags added to a hit's: the light group only where none is set yet.
inline void add_object_flags(uint32_t* flags, uint32_t outer) {
    *flags |= (*flags & kLightGroupMask) ? outer & ~kLightGroupMask : outer;
}

struct Hit {
    double t = kInfinity;
    Vec3 p;        // world-space hit point
    Vec3 p_error;  // absolute error bound of p, for offset_ray_origin()
    // Geometric normal, world space, unit length, pointing out of the solid the surface
    // bounds (flipped for `inverse` and for surfaces a CSG difference cuts with). Integrators
    // compare it with the ray direction to know whether a ray enters or leaves.
    Vec3 ng;
    // Shading normal (interpolated for smooth triangles), unit length, same side as ng.
    Vec3 n;
    Vec2 uv;             // surface parameterization (uv_mapping); valid if has_uv
    bool has_uv = false;
    // dp/du and dp/dv of the uv parameterization, world space; zero where the shape does not
    // know them (meshes with uvs fill them: tangents for bump and normal maps).
    Vec3 dpdu, dpdv;
    int material = -1;   // resolved Scene::materials id (CSG inheritance applied)
    uint32_t flags = 0;  // ObjectFlags
    AttributePoint attributes;  // meshes with named attributes
    int object = -1;     // index of the top-level scene object that was hit
    // The primitive hit and the point in its space, for Primitive::texture_blend (blob
    // component textures); null where the shape has none.
    const class Primitive* blend_source = nullptr;
    Vec3 blend_point;
};

}  // namespace glint::render
