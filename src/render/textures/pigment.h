// Pigment evaluation: POV-Ray 3.7's Compute_Pigment (texture/pigment.cpp, pattern/pattern.cpp,
// support/imageutil.cpp) for plain colors, checker, gradient with color_map and image_map.
// Used by the Whitted integrator for surfaces, shadow rays and the sky sphere.
#pragma once

#include "render/textures/image_texture.h"
#include "scene/texture.h"

namespace glint::render {

// Where a pigment is evaluated: the world-space point and, when the surface has them, its
// uv coordinates (for uv_mapping).
struct PatternPoint {
    Vec3 p;
    Vec2 uv;
    bool has_uv = false;
};

class PigmentEvaluator {
public:
    // `textures` may be null when the scene has no image maps.
    explicit PigmentEvaluator(const TextureCache* textures) : textures_(textures) {}

    // Returns false where POV-Ray finds no color (outside an image_map used `once`); `out` is
    // then fully clear, like POV-Ray's <1,1,1,0,1>.
    bool evaluate(const scene::Pigment& pigment, const PatternPoint& at, scene::ColorFT* out) const;

    // Pattern value in [0, 1] of a continuous or block pattern at a pattern-space point,
    // after frequency, phase and wave shaping (Evaluate_TPat).
    static double pattern_value(const scene::Pigment& pigment, const Vec3& local);

private:
    // `parent` is the world point (or (u, v, 0) under uv_mapping); every pigment, nested
    // entries included, carries its full pattern -> world transform.
    bool eval(const scene::Pigment& pigment, const Vec3& parent, scene::ColorFT* out) const;
    bool image_map(const scene::Pigment& pigment, const Vec3& local, scene::ColorFT* out) const;

    const TextureCache* textures_;
};

// POV-Ray's default color_map for patterns without one (pigment.cpp Gray_Default_Map):
// black at 0 to white at 1.
const std::vector<scene::ColorMapEntry>& default_color_map();

}  // namespace glint::render
