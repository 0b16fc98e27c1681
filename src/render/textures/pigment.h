// Pigment evaluation: POV-Ray 3.7's Compute_Pigment (texture/pigment.cpp, pattern/pattern.cpp,
// support/imageutil.cpp): plain colors, every pattern of render/textures/pattern.h with its
// color_map (or POV-Ray's default map), pigment_map, block-pattern entries, average and
// image_map. Used by the Whitted integrator for surfaces, shadow rays and the sky sphere.
#pragma once

#include "render/textures/image_texture.h"
#include "render/textures/pattern.h"
#include "scene/texture.h"

namespace glint::render {

// Where a pigment is evaluated: the world-space point and, when the surface has them, its
// uv coordinates (for uv_mapping).
struct PatternPoint {
    Vec3 p;
    Vec2 uv;
    bool has_uv = false;
    // The surface normal facing the ray, before perturbation (PatternContext::normal), when
    // the point is on a surface a ray hit.
    const Vec3* normal = nullptr;
    // The direction of the ray that met the surface (PatternContext::ray_dir).
    const Vec3* ray_dir = nullptr;
};

// Where uv_mapping evaluates a pattern: (u, v, 0) from the shape's own parameterization, and
// on shapes that have none the world point's x and y, as POV-Ray's ObjectBase::UVCoord
// answers for them (planes, cones, CSG, blobs, ...).
inline Vec3 uv_mapped(const PatternPoint& at) {
    return at.has_uv ? Vec3(at.uv.x, at.uv.y, 0) : Vec3(at.p.x, at.p.y, 0);
}

// The point an object's textures see: the surface point, or under the object's own
// `uv_mapping` (scene::Material::uv_points) its uv point, for every texture of the object.
inline PatternPoint texture_point(const PatternPoint& at, bool uv_points) {
    if (!uv_points) return at;
    PatternPoint q = at;
    q.p = uv_mapped(at);
    return q;
}

class PigmentEvaluator {
public:
    // `textures` may be null when the scene has no image maps.
    explicit PigmentEvaluator(const TextureCache* textures, PatternContext ctx = {})
        : textures_(textures), ctx_(ctx) {
        if (!ctx_.textures) ctx_.textures = textures;
    }

    // Returns false where POV-Ray finds no color (outside an image_map used `once`); `out` is
    // then fully clear, like POV-Ray's <1,1,1,0,1>.
    bool evaluate(const scene::Pigment& pigment, const PatternPoint& at, scene::ColorFT* out) const;

    // Pattern value in [0, 1] of a continuous pattern (the entry index of a block pattern) at
    // a pattern-space point, after warps, frequency, phase and wave shaping (Evaluate_TPat).
    double pattern_value(const scene::Pigment& pigment, const Vec3& local) const;

    const PatternContext& context() const { return ctx_; }
    const TextureCache* textures() const { return textures_; }

private:
    // `parent` is the world point (or (u, v, 0) under uv_mapping); every pigment, nested
    // entries included, carries its full pattern -> world transform.
    bool eval(const scene::Pigment& pigment, const Vec3& parent, scene::ColorFT* out) const;
    bool image_map(const scene::Pigment& pigment, const Vec3& local, scene::ColorFT* out) const;

    const TextureCache* textures_;
    PatternContext ctx_;
};

// POV-Ray's map_pos: the image coordinates (wrapped, rows top-down) of a pattern-space point
// for an image_map/bump_map; false where the point is off an image used `once`.
bool image_map_position(const scene::ImageMap& im, const ImageTexture& image, const Vec3& q,
                        double* xc, double* yc);
// image_colour_at: the image's color (with filter/transmit all) at image coordinates, with the
// map's interpolation. `index`, when given, receives POV-Ray's palette index there (the
// corners' indices blended by the same weights and truncated), -1 for other images.
scene::ColorFT image_map_sample(const scene::ImageMap& im, const ImageTexture& image, double xc,
                                double yc, int* index = nullptr);

// POV-Ray's material_map(): the entry of a material_map texture (kind ImageMap) at the warped
// pattern-space point `q`. A palette image's pixel gives its index (with `interpolate`, the
// neighbours' indices blended and truncated), another image its red value times 255; off an
// image used `once` it is 0; an index past the entry count wraps around it, one equal to the
// count takes the last entry.
const scene::Texture& material_map_entry(const scene::Texture& tex, const TextureCache* textures,
                                         const Vec3& q);

// POV-Ray's Search_Blend_Map over map values: the entries around `value` (the same one when
// it is outside the map or exactly on an entry) and the fraction between them.
struct BlendPick {
    size_t prev = 0, cur = 0;
    double fraction = 0;
};
template <class Entry>
BlendPick search_blend_map(const std::vector<Entry>& map, double value) {
    BlendPick b;
    const size_t last = map.size() - 1;
    if (value >= map[last].value) {
        b.prev = b.cur = last;
    } else {
        while (value > map[b.cur].value) b.prev = b.cur++;
    }
    if (value == map[b.cur].value) b.prev = b.cur;
    if (b.prev != b.cur)
        b.fraction = (value - map[b.prev].value) / (map[b.cur].value - map[b.prev].value);
    return b;
}

// The entry of a block pattern for its value (an index); out-of-range values clamp.
inline size_t block_index(double value, size_t count) {
    if (!(value > 0)) return 0;
    size_t i = static_cast<size_t>(value);
    return i >= count ? count - 1 : i;
}

// POV-Ray's default color_map for patterns without one (pigment.cpp Post_Pigment): bozo,
// wood, mandel, radial, agate and marble have their own; the rest Gray_Default_Map, black at 0
// to white at 1.
const std::vector<scene::ColorMapEntry>& default_color_map(
    scene::PatternKind kind = scene::PatternKind::Gradient);

}  // namespace glint::render
