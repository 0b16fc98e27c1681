// A node graph's closures (render/shader/closures.h) into the path tracer's closure set, split
// as Cycles 3.4 splits them (svm_node_closure_bsdf): the Principled BSDF's diffuse, reflection
// and glass lobes as one Bsdf, its sheen and clearcoat as lobes of their own, its subsurface
// as a BSSRDF with Burley's retro-reflection beside it; the other BSDFs as single lobes
// (docs/pbr-mapping.md).
#pragma once

#include "render/bsdf/closure_set.h"
#include "render/shader/closures.h"

namespace glint::render {

// Adds closure `c` to `set`. `n` is the closure's normal turned to the outside, `outside` the
// sign that turns the closure's vectors there; `shade` rescales for alpha skipping;
// `diffuse_ancestor` says a diffuse bounce came before on the path (Cycles then draws
// subsurface as diffuse). Whether a sampled bounce was diffuse (Light Path, bounce limits) is
// the sampled lobe's.
void add_graph_closure(ClosureSet& set, const shader::Closure& c, const Vec3& n,
                       double outside, double shade, bool diffuse_ancestor);

}  // namespace glint::render
