// Lights as the path tracer sees them, prepared once per render from the IR:
// - POV-Ray point, spot (the radius/falloff/tightness cone of POV-Ray's spot attenuation, a
//   smooth cubic between radius and falloff), parallel lights, and area lights (a rectangle
//   axis1 x axis2 around the location, sampled uniformly; like POV-Ray's grid of point lights
//   it emits the same in every direction and is invisible to camera and BSDF rays; with
//   `circular`, the ellipse inscribed in that rectangle). A POV-Ray light of color C delivers
//   the irradiance pi * C * cos * fade, so a white Lambert surface
//   shows C * cos as POV-Ray's diffuse 1.0 shows it (docs/pbr-mapping.md).
// - Blender lights (blender_light): as Cycles 3.4 samples and shows them (blender_lights.h);
//   camera and BSDF rays that pass through their discs, rectangles, ellipses and sun discs
//   collect the emission with MIS weights (blender_emission).
// - Emitting shapes (objects and union parts whose material emits a constant radiance): triangles
//   and meshes, spheres and discs, in one slot, chosen from the shading point by a light tree
//   (light_tree.h) over every sphere, disc and triangle (an object with many triangles is one
//   item whose triangles are then chosen by area times emitted radiance).
//   Discs (any affine transform) are sampled uniformly by area; triangles too, except where
//   Cycles 3.4 samples them by solid angle (seen from a point closer to the triangle's plane
//   than its longest edge, the triangle belonging to an object with at most 64 emitting
//   triangles so a BSDF hit can be matched to it): uniformly over the spherical triangle
//   (Arvo 1995), which removes the 1/r^2 noise near large emitters. A sphere under a
//   similarity transform, seen from outside, is sampled by the cone of directions it subtends
//   (uniform in solid angle, pbrt-v4's Sphere::Sample); from inside, or an ellipsoid (a
//   non-uniformly scaled sphere), uniformly by object-space area, with the world area density
//   divided by the transform's area scale at the point. BSDF rays that hit an emitter are
//   weighted by MIS (power heuristic) with emitter_pdf(), the exact pdf of the same choice.
//   Emitters inside unions (obj_file's OBJ parts) are found through the tree; a BSDF hit on an
//   object with several is matched to the sphere or disc it lies on, else to its triangles.
//   Emitters that are clipped, inverse, inside merge/intersection/difference, or other shapes
//   leave their whole object to BSDF sampling (BSDF rays that hit it count in full).
// - The environment (background color, with the sky_sphere laid over it as POV-Ray 3.7 does):
//   uniform over the sphere when it is the same everywhere, else by the luminance table of
//   environment.h (an HDR sky); the integrator evaluates its radiance.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "render/lights/blender_lights.h"
#include "render/lights/environment.h"
#include "render/lights/light_tree.h"
#include "render/ray.h"
#include "render/sampling/sampler.h"
#include "scene/scene.h"

namespace glint::render {

struct PathLightSample {
    Vec3 wi;                // unit direction from the shading point towards the light
    double dist = 0;        // distance to the light sample along wi (kInfinity: far away)
    Color value;            // radiance / pdf (delta lights: the irradiance factor)
    double pdf = 0;         // solid-angle pdf of this sample; 0 for lights BSDFs cannot hit
    bool environment = false;  // value is 1 / pdf: multiply by the environment along wi
};

class PathLights {
public:
    // `emission[m]`: the emitted radiance of material m where it is constant (black otherwise).
    // `environment`: the integrator's environment radiance along a unit world direction; with
    // `textures`, the sky_sphere's images size its sampling table. Without `environment` a
    // non-uniform environment is sampled uniformly.
    // `world`: the scene's world is a node graph (Blender) that emits everywhere alike (1) or
    // varies over the sphere (2); 0: the IR's background and sky sphere say.
    // `light_tree`: emitters are picked from the shading point by the light tree; false: by
    // their power alone.
    PathLights(const scene::Scene& scene, const std::vector<Color>& emission,
               const EnvironmentDistribution::Radiance& environment = {},
               const TextureCache* textures = nullptr, int world = 0, bool light_tree = true);

    // Light slots next-event estimation samples: each POV-Ray or Blender light, all emitting
    // shapes together (one light tree), the environment; every one of them at each vertex
    // while there are at most kSampleAllMax. Past that the lights with a place (all but
    // parallel, cylinder and sun lights) join the emitters' tree, which picks one light per
    // vertex from the shading point.
    int count() const { return static_cast<int>(nee_.size()); }
    // The probability a slot is chosen for one shading point (1 when all are sampled).
    double select_prob() const { return sample_all() ? 1.0 : 1.0 / std::max(1, count()); }
    bool sample_all() const { return count() <= kSampleAllMax; }
    bool sample(int slot, const Vec3& p, Sample2 u, PathLightSample* out) const;

    bool has_environment() const { return has_env_; }
    // Whether camera or BSDF rays can meet Blender lights (blender_emission may not be black).
    bool has_visible_blender() const { return visible_blender_; }
    // The emission of the Blender lights that the ray from `from` along the unit `dir` meets
    // at distances in (tmin, tmax] (kInfinity: the ray left the scene, where suns show), each
    // weighted by MIS against `bsdf_pdf`, the solid-angle pdf of the BSDF sample that chose
    // `dir` at `from` (negative for camera rays and delta bounces: weight 1). Camera rays
    // see only the lights with visible_camera.
    Color blender_emission(const Vec3& from, const Vec3& dir, double tmin, double tmax,
                           double bsdf_pdf, bool camera_ray) const;
    // Solid-angle pdf with which light sampling would have chosen the unit direction `dir`
    // towards the environment (slot selection included).
    double environment_pdf(const Vec3& dir) const;
    // Whether BSDF rays hitting this object could have been light-sampled.
    bool emitter_object(int object) const {
        return object >= 0 && object < static_cast<int>(object_emitter_.size()) &&
               object_emitter_[object] != kNotSampled;
    }
    // Solid-angle pdf (slot selection included) with which light sampling from `from` would
    // have chosen the point `q` with geometric normal `ng` and emission `le` on `object`.
    double emitter_pdf(int object, const Vec3& from, const Vec3& q, const Vec3& ng,
                       const Color& le) const;
    // Number of spheres and discs sampled as emitters (for tests and -v).
    int shape_emitters() const { return static_cast<int>(shapes_.size()); }

    static constexpr int kSampleAllMax = 8;

private:
    friend class LightEmission;  // photons leave the same lights (light_emission.h)
    enum class SlotKind { Pov, Blender, Emitters, Environment };
    struct Slot {
        SlotKind kind;
        int light = -1;  // Pov: index into the scene's lights; Blender: into blender_
    };
    struct Tri {
        Vec3 p0, e1, e2, n;  // n: unit geometric normal
        double area;
        Color le;
        bool locatable = false;  // a BSDF hit can be matched to it: solid-angle sampling allowed
    };
    // A sphere or a disc in world space.
    struct Shape {
        bool sphere = true;
        Color le;
        double weight = 0;  // world area times average emission
        // Sphere: `cone` when the transform is a similarity (world centre and radius), else
        // object-space centre and radius under `to_world`.
        bool cone = false;
        Vec3 center;
        double radius = 0;
        Transform to_world;
        // Disc: centre + rho (cos phi a1 + sin phi a2) for rho^2 in [inner2, 1], unit normal n.
        Vec3 a1, a2, n;
        double inner2 = 0, area = 0;
    };
    // The emitters of one top-level object, through nested unions; ok: all of them handled.
    struct Gathered {
        std::vector<Tri> tris;
        std::vector<Shape> shapes;
        bool ok = true;
    };
    void gather(const scene::Object& o, const Transform& to_world, int material,
                const std::vector<Color>& emission, Gathered* g) const;
    // The emitters of one top-level object: its triangles are somewhere in tris_, its shapes
    // are shapes_[first_shape, first_shape + shape_count).
    struct Group {
        bool tris = false;
        int first_shape = 0, shape_count = 0;
        int first_tri = 0, tri_count = 0;  // its triangles: tris_[first_tri, + tri_count)
    };
    // Solid angle of `t` seen from p when sample() samples it by solid angle (Arvo 1995, where
    // Cycles 3.4 does: its longest edge longer than its plane's distance), 0 for area sampling.
    // With `dirs`, also the unit directions from p to its corners.
    static double tri_solid_angle(const Tri& t, const Vec3& p, Vec3 dirs[3] = nullptr);
    // How far q is from the shape's surface, relative to its size (0 on it).
    static double off_surface(const Shape& e, const Vec3& q);
    // A box around the shape.
    static Bounds3 shape_bounds(const Shape& e);
    static constexpr int kNotSampled = -1;

    Color pov_factor(const scene::Light& l, const Vec3& from_light, double dist) const;
    // One light's sample with its chance of being chosen, `select`, folded in.
    bool sample_pov(const scene::Light& l, const Vec3& p, Sample2 u, double select,
                    PathLightSample* out) const;
    bool sample_blender(int k, const Vec3& p, Sample2 u, double select,
                        PathLightSample* out) const;
    // The light tree's bounds of a light; none for those without a place (distant ones).
    static std::optional<LightTreeItem> pov_tree_item(const scene::Light& l);
    std::optional<LightTreeItem> blender_tree_item(int k) const;
    bool sample_shape(const Shape& e, const Vec3& p, Sample2 u, PathLightSample* out) const;
    // Solid-angle pdf of sample_shape() choosing the point q from p, selection not included.
    double shape_pdf(const Shape& e, const Vec3& p, const Vec3& q) const;

    const scene::Scene& scene_;
    std::vector<Slot> slots_;  // every light (photons leave them all: light_emission.h)
    std::vector<Slot> nee_;    // the slots next-event estimation samples (count(), sample())
    std::vector<int> blender_light_index_;  // blender_[k] is the scene's light k
    std::vector<CyclesLight> blender_;
    bool visible_blender_ = false;
    std::vector<Tri> tris_;
    std::vector<Shape> shapes_;
    // The emitters as light-tree items (light_tree.h), chosen from the shading point: each
    // sphere and disc, each triangle of an object with few (a BSDF hit finds its triangle),
    // and each object with many triangles as one item whose triangles are then chosen by area
    // times emission (so a hit needs no match: the area density is the same on all of them).
    struct EmitterItem {
        enum class Kind { Tri, Shape, Group, PovLight, BlenderLight } kind;
        int index;  // into tris_, shapes_, groups_, the scene's lights or blender_
    };
    std::vector<EmitterItem> items_;
    LightTree emitter_tree_;
    std::vector<int> tri_item_, shape_item_;  // their item, -1 inside a group item
    std::vector<int> group_item_;             // a many-triangle group's item, else -1
    std::vector<int> blender_item_;           // a Blender light's item, -1: a slot of its own
    std::vector<double> tri_cdf_;  // group items: cumulative weight within the group, in (0, 1]
    std::vector<double> group_weight_;  // group items: the sum of area * average emission
    // The triangle of a group item for u in [0, 1) (*u rescaled) and its chance.
    int pick_group_tri(int group, double* u, double* prob) const;
    std::vector<Group> groups_;
    std::vector<int> object_emitter_;  // per object: kNotSampled or a groups_ index
    bool has_env_ = false;
    std::optional<EnvironmentDistribution> env_;  // absent: uniform sphere sampling
};

}  // namespace glint::render
