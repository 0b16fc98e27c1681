// POV-Ray 3.7's pattern functions (backend/pattern/pattern.cpp, warps.cpp) and the special
// normal perturbations of backend/texture/normal.cpp. Pigments, normals and textures call
// evaluate_pattern() with a pattern-space point; the normal code calls special_normal() for the
// patterns POV-Ray perturbs directly (bumps, dents, ripples, waves, wrinkles, quilted, facets).
// Everything here is stateless and allocation-free per call.
#pragma once

#include "core/math.h"
#include "scene/function.h"
#include "scene/texture.h"

namespace glint::render {

class TextureCache;

// Scene-wide settings a pattern depends on (global_settings).
// Whether a point lies inside an object pattern's object (Scene::pattern_objects), for
// PatternKind::Object; the renderer's geometry answers (prepare/pattern_objects.h).
class PatternObjects {
public:
    virtual ~PatternObjects() = default;
    virtual bool inside(int object, const Vec3& p) const = 0;
};

struct PatternContext {
    int noise_generator = 2;   // global_settings { noise_generator N }; POV-Ray 3.7 default 2
    int number_of_waves = 10;  // global_settings { number_of_waves N }: ripples and waves
    // Scene::functions, for PatternKind::Function (params.function indexes it); null: the
    // function pattern evaluates to 0.
    const std::vector<scene::Function>* functions = nullptr;
    // Scene::pattern_objects' inside tests; null: an object pattern is outside everywhere.
    const PatternObjects* objects = nullptr;
    // Image maps for pigment functions called from functions (`function { pigment { image_map
    // ... } }`); null: the scene has none.
    const TextureCache* textures = nullptr;
    // The surface's normal where the pattern is evaluated on one (world space, facing the ray,
    // before any normal perturbation: POV-Ray's PNormal), for the slope pattern; null
    // elsewhere (media, functions), where slope is 0.
    const Vec3* normal = nullptr;
    // The direction of the ray that met the surface, for the aoi pattern; null elsewhere.
    const Vec3* ray_dir = nullptr;
};

// POV-Ray's Warp_EPoint + Evaluate_TPat.
//
// `p` is the point in pattern space: the caller has already applied the inverse of the
// pattern's own transform (Pigment/Normal/Texture::transform, POV-Ray's leading TRANSFORM_WARP)
// or taken (u, v, 0) under uv_mapping. This function then applies params.warps in list order
// (a ClassicTurbulence warp is skipped for marble and wood, which use the turbulence inside
// the pattern function; agate, spiral1 and spiral2 do too, as POV-Ray's do, and also get the
// warp), clamps the point to +-1e17, evaluates the pattern and, for continuous patterns,
// applies frequency/phase (POV-Ray's fmod by 1.00001) and the wave type.
//
// Continuous patterns return a value in [0, 1] (POV-Ray's modulus is 1.00001, so just above 1
// is possible; with frequency 0 a pattern's raw value, e.g. granite's, may pass 1: a map
// lookup clamps it). Block patterns (Checker, Brick, Hexagon, Square, Triangular, Cubic; see
// is_block_pattern) return the entry index as a double (checker/brick 0..1, hexagon 0..2,
// square 0..3, triangular 0..5, cubic 0..5) with no frequency or wave shaping. ImageMap,
// Plain, Average and Function are not handled here (they return 0; the callers evaluate them).
//
// A pattern's noise_generator is params.noise_generator when non-zero, else ctx's.
//
// The IR must carry POV-Ray's parse-time defaults, which this function does not invent:
// frequency 0 for quilted (and image_pattern, block patterns); triangle_wave for marble, wood,
// spiral1 and spiral2; the gradient vector normalized; spiral arms; mandel/julia iterations.
// Agate without a ClassicTurbulence warp uses octaves 6, omega 0.5, lambda 2 (POV-Ray always
// gives agate one). Marble, wood, agate and spirals read the first ClassicTurbulence warp.
// Warp conventions: Transform holds the transform as written (`warp { scale 2 }` enlarges) and
// is applied inversely, like the pattern's own; Repeat's flip is as written (a non-zero
// component mirrors that axis); BlackHole's turbulence.amount is its `turbulence` (the
// uncertainty), and POV-Ray's parse-time centre/repeat adjustment is applied here. Mandel and
// julia take exponents 2..33 (truncated and clamped, as POV-Ray's parser limits them).
double evaluate_pattern(scene::PatternKind kind, const scene::PatternParams& params, const Vec3& p,
                        const PatternContext& ctx);

// What evaluating the scene's user functions needs (function patterns, isosurfaces): pattern
// functions go through the pattern code with `ctx`, which must outlive the result.
scene::FunctionEnv user_function_env(const PatternContext& ctx);

// Checker, Brick, Hexagon, Square, Triangular, Cubic.

bool is_block_pattern(scene::PatternKind kind);

// Applies params.warps to a pattern-space point (POV-Ray's Warp_EPoint without the pattern's own
// transform), for callers that need the warped point itself. `kind` matters only for the
// ClassicTurbulence warp (skipped for Marble and Wood).
Vec3 warp_point(scene::PatternKind kind, const scene::PatternParams& params, const Vec3& p);

// True for the patterns POV-Ray perturbs a normal with directly instead of through the slope of
// the pattern value: Bumps, Dents, Ripples, Waves, Wrinkles, Quilted, Facets. (A normal with a
// normal_map, slope_map or average takes POV-Ray's generic path instead, except that a normal
// with a normal_map never reaches here; a slope_map does not change these kinds' special path.)
bool has_special_normal(scene::PatternKind kind);

// POV-Ray's Perturb_Normal for the kinds of has_special_normal (normal.cpp bumps(), dents(),
// ripples(), waves(), wrinkles(), quilted(), facets()).
//
// What the caller passes (for a Normal `nrm` at world point P with world normal N):
//   p_pattern = nrm.transform.inverse_point(P)        (or (u, v, 0) under uv_mapping);
//               this function applies nrm.params.warps itself, like evaluate_pattern.
//   normal    = normalize(nrm.transform.inverse().normal(N)): the world normal carried into
//               pattern space (POV-Ray's Warp_Normal, MInvTransNormal), normalized.
//   amount    = nrm.amount (bump_size), unscaled.
// Returns the perturbed normal in pattern space, normalized. `warp { transform }` entries of
// params.warps are carried both ways here. The caller maps the result back to world space with
// normalize(nrm.transform.normal(result)) (POV-Ray's UnWarp_Normal); with an identity transform
// the result is already the world normal. Ripples and waves use params.frequency/phase here (not
// as a post-shaping of a value); facets ignores `amount` unless `coords` is given, as POV-Ray.
Vec3 special_normal(scene::PatternKind kind, const scene::PatternParams& params,
                    const Vec3& p_pattern, const Vec3& normal, double amount,
                    const PatternContext& ctx);

}  // namespace glint::render
