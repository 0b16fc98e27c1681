// Everything that can be hit, built from the IR once per render: shapes in object space
// behind their transforms, CSG trees, clipping, and a SAH BVH over the top-level objects.
// Integrators only see intersect() and occluded().
#pragma once

#include <memory>
#include <vector>

#include "core/log.h"
#include "render/ray.h"
#include "scene/features.h"
#include "scene/scene.h"

namespace glint::render {

class MaterialTable;
struct GradientNote;  // render/shapes/primitive.h

class Geometry {
public:
    virtual ~Geometry() = default;

    // Closest hit with 0 < t < ray.tmax. Deterministic: equal t ties break by object order.
    virtual bool intersect(const Ray& ray, Hit* hit) const = 0;
    // Any hit with 0 < t < ray.tmax by an object without kNoShadow.
    virtual bool occluded(const Ray& ray) const = 0;
    // The same answer, testing first the object *hint names (what blocked the previous
    // shadow ray towards the same light, POV-Ray's shadow cache) and leaving there the one
    // that blocks this ray. Any value of *hint is valid; -1 names none. Only the speed depends
    // on it, never the result.
    virtual bool occluded(const Ray& ray, int* hint) const {
        (void)hint;
        return occluded(ray);
    }
    // What a shadow ray meets, for the Whitted shadow walk through filtering objects: nothing
    // (the light arrives whole), an object none of whose surfaces can let light through
    // (materials/opacity.h: the light is blocked whatever else is there), or only objects that
    // may (the walk must look). Any-hit queries, so cheaper than the walk's closest hits.
    // Geometries that cannot tell opaque objects apart answer Other for every blocked ray.
    enum class Blocker { None, Opaque, Other };
    virtual Blocker shadow_blocker(const Ray& ray, int* hint) const {
        return occluded(ray, hint) ? Blocker::Other : Blocker::None;
    }
    // The closest hit with 0 < t < ray.tmax on scene object `object` alone, whatever else is
    // in the way (Cycles' local intersection: a subsurface walk inside one object).
    virtual bool intersect_object(const Ray& ray, int object, Hit* hit) const {
        (void)ray, (void)object, (void)hit;
        return false;
    }
    // After the render: the isosurfaces' gradient reports (Primitive::gradient_notes).
    virtual void gradient_notes(std::vector<GradientNote>* out) const { (void)out; }
    virtual Bounds3 bounds() const = 0;  // may be infinite (planes)
    // The bounds of the objects whose bounds are finite (empty when there are none).
    virtual Bounds3 finite_bounds() const { return bounds().is_infinite() ? Bounds3{} : bounds(); }
};

// Degenerate input (zero-area triangles, non-finite vertices, empty meshes) is skipped with a
// warning; invalid input throws glint::Error. The material table's opacity decides which
// objects shadow_blocker() may call opaque.
std::unique_ptr<Geometry> build_geometry(const scene::Scene& scene,
                                         const scene::Features& features,
                                         const MaterialTable& materials, Diagnostics& diag);
// The same with the opacity of a table of its own, made without the images (so any image map
// may let light through): for one-off questions (parse-time trace(), tests).
std::unique_ptr<Geometry> build_geometry(const scene::Scene& scene,
                                         const scene::Features& features, Diagnostics& diag);

}  // namespace glint::render
