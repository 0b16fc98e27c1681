// Scene pieces the path tracer's tests share: plain Lambert and emitting materials as an
// importer fills them (Pbr, not derived from a POV-Ray finish), and render options.
#pragma once

#include "render/render.h"
#include "scene/scene.h"

namespace glint::render::path_test {

// A Lambert surface of albedo c: no reflection lobe (specular and metallic 0).
inline scene::Material lambert(Color c) {
    scene::Material m;
    m.pbr.derived = false;
    m.pbr.base_color = c;
    m.pbr.specular = 0;
    m.pbr.metallic = 0;
    m.pbr.roughness = 1;
    return m;
}

// A black surface emitting radiance le (both sides).
inline scene::Material emitter(double le) {
    scene::Material m = lambert(Color(0, 0, 0));
    m.pbr.emission = Color(le, le, le);
    m.pbr.emission_strength = 1;
    return m;
}

// The path tracer at w x h, spp samples per pixel, `depth` bounces, on two threads.
inline RenderOptions path_options(int w, int h, int spp, int depth) {
    RenderOptions o;
    o.width = w;
    o.height = h;
    o.integrator = IntegratorKind::Path;
    o.spp = spp;
    o.max_depth = depth;
    o.threads = 2;
    return o;
}

}  // namespace glint::render::path_test
