#include "scene/shape.h"

namespace glint::scene {

const char* shape_name(const Shape& shape) {
    static constexpr const char* kNames[] = {"sphere",   "plane", "box",      "cylinder",
                                             "cone",     "disc",  "torus",    "triangle",
                                             "smooth_triangle", "mesh", "csg",
                                             "quadric",  "polygon", "prism", "lathe", "sor",
                                             "superellipsoid", "blob", "height_field", "poly",
                                             "text", "julia_fractal", "bicubic_patch",
                                             "isosurface", "sphere_sweep", "ovus", "parametric"};
    static_assert(std::size(kNames) == std::variant_size_v<Shape>);
    if (const auto* csg = std::get_if<Csg>(&shape)) {
        switch (csg->op) {
            case CsgOp::Union: return "union";
            case CsgOp::Merge: return "merge";
            case CsgOp::Intersection: return "intersection";
            case CsgOp::Difference: return "difference";
        }
    }
    return kNames[shape.index()];
}

}  // namespace glint::scene
