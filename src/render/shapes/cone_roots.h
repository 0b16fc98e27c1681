// Where a ray meets a cone or cylinder (cone.cpp), in the canonical frame: axis along z from
// z = 0 (radius r0) to z = 1 (radius r1). Built twice, for any x86-64 and with FMA
// instructions, with the same bits from both; cone_roots() picks one for this CPU once.
#pragma once

#include "render/ray.h"

namespace glint::render {

struct ConeShape {
    double r0, r1;
    bool open;  // no caps
};

struct ConeRoot {
    double t;
    int part;  // 0 side, 1 base cap (z = 0), 2 top cap (z = 1)
};

// Every crossing of the surface with err < t < tmax, where err bounds the root's own rounding
// error: up to two on the side and one on each cap, in no particular order. Returns how many.
using ConeRootsFn = int (*)(const ConeShape& cone, const Ray& ray, double tmax, ConeRoot out[4]);

// The build for this CPU: with FMA where it has it.
ConeRootsFn cone_roots();
// Each build by name (tests compare them); cone_roots_fma() is null on a CPU without FMA.
ConeRootsFn cone_roots_generic();
ConeRootsFn cone_roots_fma();

}  // namespace glint::render
