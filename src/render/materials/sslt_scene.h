// An SsltScene (sslt.h) made of the classic renderer's parts: its geometry, its POV-Ray
// lights, and callbacks for shadows and for tracing rays on from inside a subsurface sample.
#pragma once

#include <functional>
#include <utility>
#include <vector>

#include "render/lights/light.h"
#include "render/materials/sslt.h"
#include "render/prepare/prepared_scene.h"

namespace glint::render {

// The subsurface estimate's view of the classic renderer: every object, the POV-Ray lights
// with their shadows, and rays traced on from inside one subsurface sample (where the samples
// drop to one of each kind, and stop one level further down).
class CallbackSsltScene final : public SsltScene {
public:
    using Shadow = std::function<Color(size_t, const Hit&, const LightSample&)>;
    using Trace = std::function<Color(const Ray&, double)>;
    CallbackSsltScene(const Geometry& g, const std::vector<PreparedLight>& lights,
                      bool shadows, Shadow shadow, Trace trace)
        : geometry_(g), lights_(lights), shadows_(shadows), shadow_(std::move(shadow)),
          trace_(std::move(trace)) {}
    bool intersect(const Vec3& origin, const Vec3& dir, double tmax, Hit* hit) const override {
        Ray r;
        r.origin = origin;
        r.dir = dir;
        r.tmax = tmax;
        return geometry_.intersect(r, hit);
    }
    size_t light_count() const override { return lights_.size(); }
    bool light_direction(size_t k, const Vec3& p, Vec3* dir) const override {
        LightSample ls;
        if (lights_[k].light().blender || !lights_[k].sample(p, &ls)) return false;
        *dir = ls.dir;
        return true;
    }
    Color light(size_t k, const Hit& at, Vec3* dir) const override {
        const PreparedLight& light = lights_[k];
        LightSample ls;
        if (light.light().blender || !light.sample(at.p, &ls)) return Color();
        if (!(std::fabs(ls.color.r) >= kPovEpsilon || std::fabs(ls.color.g) >= kPovEpsilon ||
              std::fabs(ls.color.b) >= kPovEpsilon))
            return Color();
        *dir = ls.dir;
        return shadows_ && light.casts_shadows() ? shadow_(k, at, ls) : ls.color;
    }
    Color trace(const Ray& ray, double weight) const override { return trace_(ray, weight); }

private:
    const Geometry& geometry_;
    const std::vector<PreparedLight>& lights_;
    bool shadows_;
    Shadow shadow_;
    Trace trace_;
};


}  // namespace glint::render
