// The shading normal the path tracer's BSDFs see. An interpolated (or bumped) normal can tilt
// so far from the geometric one that the view's mirror direction points into the surface: near
// the silhouettes of smooth meshes, a glossy lobe would then reflect mostly into the solid and
// its paths end black. Cycles 3.4 bends such a normal, for every closure, towards the geometric
// normal just far enough that the mirror direction clears the surface; the path integrator does
// the same so that both converge to the same image.
#pragma once

#include "core/math.h"

namespace glint::render {

// `ng` and `n` are unit normals on the same side (either side of the surface), `wo` the unit
// direction towards the viewer. Returns `n` itself where its mirror direction of wo rises at
// least min(0.9 (ng . wo), 0.01) above the surface (seen from wo's side); otherwise the unit
// normal in the plane of ng and n whose mirror direction rises exactly that much, on the side
// n was given; ng (signed likewise) when no such normal exists.
Vec3 valid_reflection_normal(const Vec3& ng, const Vec3& wo, const Vec3& n);

}  // namespace glint::render
