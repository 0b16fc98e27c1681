// Blender's Sky Texture node (ShaderNodeTexSky) as Cycles 3.4 evaluates it, for its three sky
// types:
//
//   PREETHAM      Preetham, Shirley and Smits, "A Practical Analytic Model for Daylight"
//                 (1999): the Perez distribution in xyY, with Cycles' sync-time constants
//                 (scene/shader_nodes.cpp) and kernel (kernel/svm/sky.h).
//   HOSEK_WILKIE  Hosek and Wilkie, "An Analytic Model for Full Spectral Sky-Dome Radiance"
//                 (2012), CIE XYZ version: configuration cooked in double precision from the
//                 published coefficients (sky_hosek_data.cpp), evaluated in float, scaled by
//                 2 pi / 683.
//   NISHITA       Blender's single-scattering atmosphere (intern/sky, "Nishita improved"):
//                 a 512 x 128 table of sky XYZ radiance precomputed at prepare() time and
//                 sampled bilinearly (Cycles' image texture lookup, extension EXTEND), plus a
//                 sun disc interpolated between two precomputed sun radiances, with limb
//                 darkening; below the horizon the horizon row fades to black at z = -0.4.
//
// Results are in scene-linear Rec.709 (Blender's default colour configuration): XYZ goes
// through Cycles' film XYZ -> RGB matrix (converter_nodes.h kCyclesXyzToRgb) and negative
// channels become zero, as Cycles 3.4 does for all three types. The arithmetic follows
// Blender's code in single precision (double where Blender's Hosek-Wilkie code uses double),
// so values agree with Blender 3.4.1's renders to about 1e-5 relative
// (tests/unit/shader_sky_test.cpp).
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "render/shader/float3.h"

namespace glint::render::shader {

// ShaderNodeTexSky.sky_type.
enum class SkyType { PREETHAM, HOSEK_WILKIE, NISHITA };
// Parses Blender's identifier ('PREETHAM', 'HOSEK_WILKIE', 'NISHITA'); false if unknown.
bool parse_sky_type(std::string_view id, SkyType* out);

// The node's settings under Blender's property names; the defaults are Blender's.
struct SkyParams {
    SkyType type = SkyType::NISHITA;
    // PREETHAM and HOSEK_WILKIE. sun_direction points at the sun (world space, Z up; it is
    // normalized here as Blender's sync does).
    float3 sun_direction{0.0f, 0.0f, 1.0f};
    float turbidity = 2.2f;      // Blender's range [1, 10]
    float ground_albedo = 0.3f;  // HOSEK_WILKIE only, [0, 1]
    // NISHITA. Angles in radians; sun_rotation 0 puts the sun towards +Y, increasing towards
    // +X. sun_size is the disc's angular diameter (Cycles uses at least 0.0005); altitude in
    // metres (Cycles clamps it to [1, 59999]).
    bool sun_disc = true;
    float sun_size = 0.009512044f;
    float sun_intensity = 1.0f;
    float sun_elevation = 0.2617994f;  // 15 degrees
    float sun_rotation = 0.0f;
    float altitude = 0.0f;
    float air_density = 1.0f;
    float dust_density = 1.0f;
    float ozone_density = 1.0f;
};

// A Sky Texture ready to evaluate: what Cycles computes at sync/compile time, then its SVM
// kernel per direction. Copies share the Nishita table. Thread-safe to evaluate.
class SkyModel {
  public:
    // Size of the precomputed Nishita table (Cycles' SkyLoader image).
    static constexpr int kTableWidth = 512;
    static constexpr int kTableHeight = 128;

    // Does the sync-time work: the Preetham/Hosek-Wilkie configuration, or the Nishita table
    // (some 0.2 s of single-threaded work) and sun radiances.
    static SkyModel prepare(const SkyParams& params);

    // The node's Color output for the vector at its Vector input (unlinked: the direction of
    // the background ray, a unit vector in Blender world space). The vector is used as given,
    // like Cycles' kernel does (no normalization).
    float3 radiance(float3 dir) const;

    SkyType type() const { return type_; }
    // The Nishita table's texel (x, y), CIE XYZ: x along longitude, y = 0 at the horizon up
    // to the zenith (rows placed at elevation (pi/2 + pi/512) * (y / 128)^2). Zero for other
    // sky types.
    float3 table_texel(int x, int y) const;

  private:
    SkyType type_ = SkyType::NISHITA;

    // PREETHAM / HOSEK_WILKIE: the sun's spherical angles (theta from +Z, phi = atan2(x, y)),
    // the zenith radiance scale and the nine distribution coefficients per channel (Preetham
    // uses five, in Y, x, y order).
    float sun_theta_ = 0.0f;
    float sun_phi_ = 0.0f;
    float scale_[3] = {0.0f, 0.0f, 0.0f};
    float config_[3][9] = {};

    // NISHITA: sun disc radiance at its bottom and top (XYZ), the sun's elevation, its
    // rotation as Cycles passes it to the kernel (2 pi - rotation, wrapped into (0, 2 pi]),
    // the angular diameter (negative: no disc) and intensity; the sky table.
    float3 sun_bottom_;
    float3 sun_top_;
    float sun_elevation_ = 0.0f;
    float sun_rotation_ = 0.0f;
    float sun_diameter_ = -1.0f;
    float sun_intensity_ = 0.0f;
    std::shared_ptr<const std::vector<float3>> table_;

    float3 preetham(float3 dir) const;
    float3 hosek_wilkie(float3 dir) const;
    float3 nishita(float3 dir) const;
    float3 table_lookup(float x, float y) const;
};

}  // namespace glint::render::shader
