// POV-Ray's area_light shadows (trace.cpp TraceAreaLightShadowRay and
// TraceAreaLightSubsetShadowRay): a size1 x size2 grid of point samples spanning axis1 x axis2
// around the light centre, sampled at the grid's corners and subdivided where the corners
// disagree (or down to the `adaptive` level), then averaged region by region.
#pragma once

#include "render/lights/light.h"

namespace glint::render {

// Filtered light arriving at the shading point along `dir` from a sample `depth` away:
// `light` times whatever the objects in between let through. A non-owning reference to the
// caller's callable, valid during the call it is passed to: area_light_shadow runs per
// shading point and light, where a std::function holding the integrator's lambda (three
// captures, past std::function's inline storage) allocated every time.
class PointShadowFn {
public:
    template <typename F>
    PointShadowFn(const F& f)  // implicit, so a lambda can be passed directly
        : callable_(&f),
          call_([](const void* c, const Vec3& dir, double depth, const Color& light) {
              return (*static_cast<const F*>(c))(dir, depth, light);
          }) {}

    Color operator()(const Vec3& dir, double depth, const Color& light) const {
        return call_(callable_, dir, depth, light);
    }

private:
    const void* callable_;
    Color (*call_)(const void*, const Vec3&, double, const Color&);
};

// The light reaching `p` from an area light whose centre-attenuated color is `light_color`.
// With jitter, each grid sample moves by up to half a cell in each direction, by glint's own
// random numbers (POV-Ray's come from a per-thread stream that cannot be replayed).
Color area_light_shadow(const PreparedLight& light, const Vec3& p, const Color& light_color,
                        const PointShadowFn& shadow);

}  // namespace glint::render
