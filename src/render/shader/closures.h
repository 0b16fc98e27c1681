// What a shader graph is evaluated at (ShaderGlobals) and what it gives back (ClosureList):
// the BSDF closures with their weights and normals, emission, transparency and holdout, as
// Cycles' SVM leaves them in its closure array (kernel/closure, kernel/svm/closure.h).
#pragma once

#include <cstdint>
#include <string_view>

#include "core/fixed_list.h"
#include "core/math.h"
#include "render/ray.h"
#include "render/shader/float3.h"

namespace glint::render::shader {

// A volume's grids by name (a Blender Volume object's OpenVDB grids), sampled at a world
// point: a scalar grid gives its value in every channel.
class VolumeGridSource {
public:
    virtual ~VolumeGridSource() = default;
    // False when there is no grid of that name.
    virtual bool grid(std::string_view name, const Vec3& p, Vec3* value) const = 0;
};

// The shading point. Directions are unit, world space. Coordinates as Cycles' Texture
// Coordinate and Geometry nodes give them.
struct ShaderGlobals {
    float3 P;          // world position
    float3 N;          // shading normal (smooth), facing the viewer's side
    float3 Ng;         // geometric normal, facing the viewer's side
    float3 I;          // towards the viewer (the incoming ray reversed)
    float3 uv;         // the active UV map (z = 0)
    float3 generated;  // the object's texture space (its bounds) mapped to [0, 1]^3
    float3 object;     // object-space position
    float3 dPdu, dPdv; // world-space uv tangents where the mesh has uvs, else zero
    // Bump's finite differences: two steps in the surface as Cycles 3.4 takes them (the
    // pixel's footprint along make_orthonormals(Ng)), and Generated's scale (object units ->
    // texture space).
    float3 dPdx, dPdy;
    float3 generated_scale{1, 1, 1};
    float3 tangent;     // Cycles' tangent: around the texture space's Z axis, normal to N
    float3 uv_tangent;  // the normal map's tangent: dPdu where the mesh has uvs
    AttributePoint attributes;  // the mesh's named layers at P (Attribute nodes)
    const VolumeGridSource* grids = nullptr;  // a volume shader's grids at P (Volume objects)
    bool backfacing = false;
    // Object Info.
    float3 object_location;
    float3 object_color{1, 1, 1};
    float object_pass_index = 0;
    float object_random = 0;
    // Light Path: what kind of ray reached this point, and how far it travelled.
    bool camera_ray = true, shadow_ray = false, diffuse_ray = false, glossy_ray = false,
         singular_ray = false, reflection_ray = false, transmission_ray = false;
    float ray_length = 0;
    int ray_depth = 0, diffuse_depth = 0, glossy_depth = 0, transparent_depth = 0,
        transmission_depth = 0;
    // Camera Data and the Texture Coordinate node's Camera/Window outputs need the camera:
    // world -> camera-space point, and the image position of P.
    float3 camera_position;  // P in camera space (Blender: -Z forward)
    float3 window;           // P's position on the image, [0, 1]^2
    float view_distance = 0;
    // The object's transform (world -> object) for vector transforms and the object space
    // Normal output: rows of the 3x4 inverse and of the forward matrix.
    float world_to_object[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    float object_to_world[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    // The camera's frame (Cycles' camera space: X right, Y up, Z into the view) for Vector
    // Transform.
    float world_to_camera[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    float camera_to_world[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
};

// The BSDF closures glint renders. The integrator maps each onto the path tracer's models
// (render/bsdf/bsdf.h for Principled and Glass, lobe.h for the others).
enum class ClosureKind : uint8_t {
    Diffuse,      // color, roughness (Oren-Nayar above 0)
    Principled,   // base, metallic, roughness, specular, ior, transmission, sheen, clearcoat, ...
    Glossy,       // color, roughness, anisotropy and rotation about the tangent, distribution
    Glass,        // color, roughness, ior, distribution
    Refraction,   // color, roughness, ior, distribution: the refracted half of Glass
    Translucent,  // color: Lambert transmission
    Toon,         // color, size (roughness), smooth; `glossy` picks the component
    Velvet,       // color, sigma (roughness)
    Subsurface,   // the Subsurface Scattering node: color (albedo), radius, ior, anisotropy
};

// How a BSSRDF scatters under the surface (the nodes' subsurface_method / falloff): Cycles
// 3.4's random walk with the radius adjusted for albedo and IOR (its default), or with the
// radius as given (Fixed Radius); Christensen-Burley's disk sampling is drawn as Fixed Radius.
enum class SubsurfaceMethod : uint8_t { RandomWalk, FixedRadius, Burley };

// Blender's microfacet distributions (the node's `distribution`).
enum class Distribution : uint8_t { GGX, Beckmann, AshikhminShirley, MultiGGX };

struct Closure {
    ClosureKind kind = ClosureKind::Diffuse;
    Distribution distribution = Distribution::GGX;
    bool glossy = false;  // Toon: the glossy component
    Color weight;  // the closure's weight (mix factors and colours multiplied in)
    Vec3 N;        // its own shading normal (bump and normal maps are per closure)
    Vec3 T;        // tangent of anisotropic lobes (rotation applied), zero when isotropic
    Vec3 clearcoat_N;  // Principled: the clearcoat's own normal
    Color color{1, 1, 1};
    double roughness = 0;
    double metallic = 0;
    double specular = 0.5;
    double ior = 1.45;
    double transmission = 0;
    double anisotropy = 0;  // Principled's anisotropic, Anisotropic BSDF's anisotropy
    double specular_tint = 0;
    double sheen = 0, sheen_tint = 0.5;
    double clearcoat = 0, clearcoat_roughness = 0.03;
    double transmission_roughness = 0;
    double smooth = 0;  // Toon
    // Principled: the subsurface amount, radius (per channel, scene units), colour, IOR and
    // anisotropy; the Subsurface Scattering node: its radius x scale and the others (its
    // colour is `color`).
    double subsurface = 0;
    Color subsurface_radius{1, 0.2, 0.1};
    Color subsurface_color{0.8, 0.8, 0.8};
    double subsurface_ior = 1.4;
    double subsurface_anisotropy = 0;
    SubsurfaceMethod subsurface_method = SubsurfaceMethod::RandomWalk;
    double sample_weight = 0;  // |average(weight)|: the share of BSDF samples it gets
    // N and clearcoat_N are the shading point's normal (the inputs are unlinked, no bump).
    bool n_from_globals = false, clearcoat_n_from_globals = false;
};

// What one evaluation leaves: at most kMax closures (Cycles' default is 64; real graphs have a
// handful), the emitted radiance, the transparent (straight-through) weight and the holdout.
struct ClosureList {
    static constexpr int kMax = 16;
    FixedList<Closure, kMax> items;  // (unused slots cost nothing to make or copy)
    Color emission;
    Color transparent;
    Color holdout;
    // The surface's shading normal (Cycles' sd->N): N, or N bent by the material's
    // displacement; facing the viewer like the closures' normals.
    Vec3 N;
    bool overflow = false;  // a closure past kMax was dropped

    int count() const { return items.size(); }
    void add(const Closure& c) {
        if (!items.push_back(c)) overflow = true;
    }
};

// What a volume shader leaves at a point (Cycles' volume closures): extinction, the scattering
// lobes (Henyey-Greenstein, each with its share of the scattering) and the emission, all per
// unit length.
struct VolumeClosures {
    static constexpr int kMax = 8;
    Color extinction;
    Color emission;
    struct Lobe {
        Color sigma_s;
        double g = 0;
    } lobes[kMax];
    int count = 0;
};

}  // namespace glint::render::shader
