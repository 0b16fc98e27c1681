// Temporary: shapes not yet implemented report a clear error.
#include "core/error.h"
#include "render/shapes/mesh_prim.h"
#include "render/shapes/shapes.h"

namespace glint::render {
namespace {
[[noreturn]] void missing(const char* what) {
    throw Error(ErrorKind::Scene, {}, std::string(what) + " is not supported yet");
}
}  // namespace
std::unique_ptr<Primitive> make_cylinder(const scene::Cylinder&, Transform*, const char**) {
    missing("cylinder");
}
std::unique_ptr<Primitive> make_cone(const scene::Cone&, Transform*, const char**) {
    missing("cone");
}
std::unique_ptr<Primitive> make_disc(const scene::Disc&, Transform*, const char**) {
    missing("disc");
}
std::unique_ptr<Primitive> make_torus(const scene::Torus&) { missing("torus"); }
}  // namespace glint::render
