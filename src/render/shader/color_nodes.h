// Blender's COLOR shader nodes (and the ramp and curve lookups of the converter and vector
// nodes) as pure functions giving Cycles 3.4's values: Mix RGB and Mix, Hue/Saturation/Value,
// Bright/Contrast, Gamma, Invert, RGB to BW, Color Ramp, RGB Curves, Vector Curves, Float
// Curve, and the RGB <-> HSV / HSL conversions they share with Separate/Combine Color.
//
// Every function mirrors the arithmetic of Cycles' SVM kernel (intern/cycles/kernel/svm and
// util/color.h) in single precision, so that results agree with Cycles to the last bits where
// the operations are the same. Enums are named after Blender's Python enum identifiers, and
// each has a parse_* function taking that identifier.
#pragma once

#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "render/shader/float3.h"

namespace glint::render::shader {

// ---- Mix -----------------------------------------------------------------------------------

// ShaderNodeMixRGB.blend_type / ShaderNodeMix.blend_type (Blender 3.4 has no EXCLUSION).
enum class MixBlend {
    MIX,
    DARKEN,
    MULTIPLY,
    BURN,
    LIGHTEN,
    SCREEN,
    DODGE,
    ADD,
    OVERLAY,
    SOFT_LIGHT,
    LINEAR_LIGHT,
    DIFFERENCE,
    SUBTRACT,
    DIVIDE,
    HUE,
    SATURATION,
    COLOR,
    VALUE,
};
bool parse_mix_blend(std::string_view id, MixBlend* out);

// ShaderNodeMix.data_type and .factor_mode.
enum class MixDataType { FLOAT, VECTOR, RGBA };
bool parse_mix_data_type(std::string_view id, MixDataType* out);
enum class MixFactorMode { UNIFORM, NON_UNIFORM };
bool parse_mix_factor_mode(std::string_view id, MixFactorMode* out);

// The blend itself with factor t as given (Cycles' svm_mix): no clamping of t or the result.
float3 mix_blend(MixBlend blend, float t, float3 a, float3 b);

// Legacy Mix RGB node (ShaderNodeMixRGB): Cycles always clamps Fac to [0, 1]; use_clamp
// clamps the result to [0, 1].
float3 mix_rgb_node(MixBlend blend, float fac, float3 color1, float3 color2, bool use_clamp);

// Mix node (ShaderNodeMix), data type RGBA: clamp_factor clamps Factor to [0, 1] first,
// clamp_result the result.
float3 mix_color_node(MixBlend blend, float fac, float3 a, float3 b, bool clamp_factor,
                      bool clamp_result);
// Mix node, data type FLOAT: a * (1 - t) + b * t.
float mix_float_node(float fac, float a, float b, bool clamp_factor);
// Mix node, data type VECTOR, uniform factor.
float3 mix_vector_node(float fac, float3 a, float3 b, bool clamp_factor);
// Mix node, data type VECTOR, factor mode NON_UNIFORM (one factor per component).
float3 mix_vector_non_uniform_node(float3 fac, float3 a, float3 b, bool clamp_factor);

// ---- Color spaces --------------------------------------------------------------------------

// Cycles' util/color.h conversions; hue, saturation, value / lightness all in [0, 1] for
// colors in [0, 1] (no clamping is done on either side).
float3 rgb_to_hsv(float3 rgb);
float3 hsv_to_rgb(float3 hsv);
float3 rgb_to_hsl(float3 rgb);
float3 hsl_to_rgb(float3 hsl);

// ---- Color adjustment nodes ------------------------------------------------------------------

// Hue/Saturation/Value node (ShaderNodeHueSaturation).
float3 hue_saturation_value_node(float hue, float saturation, float value, float fac, float3 color);
// Bright/Contrast node (ShaderNodeBrightContrast).
float3 bright_contrast_node(float3 color, float bright, float contrast);
// Gamma node (ShaderNodeGamma): components <= 0 pass through; gamma 0 gives white.
float3 gamma_node(float3 color, float gamma);
// Invert node (ShaderNodeInvert).
float3 invert_node(float fac, float3 color);

// Cycles' luminance weights (film rgb_to_y) for Blender 3.4's default OpenColorIO
// configuration (scene linear = Rec.709): the Y row of the inverse of the XYZ -> scene linear
// matrix Cycles derives from the config's aces_interchange role, as measured from Cycles.
inline constexpr float3 kCyclesRgbToY{0.212672979f, 0.715152621f, 0.0721754432f};
// RGB to BW node (ShaderNodeRGBToBW), and Cycles' implicit color -> float conversion.
float rgb_to_bw_node(float3 color, float3 rgb_to_y = kCyclesRgbToY);

// ---- Ramps and curves --------------------------------------------------------------------------

// Entries Blender bakes a ramp or a curve mapping into for Cycles (RAMP_TABLE_SIZE).
inline constexpr int kRampTableSize = 256;

// Cycles' rgb_ramp_lookup / float_ramp_lookup over a baked table of at least 2 entries,
// sampling f in [0, 1] (entry i at f = i / (size - 1)). Outside [0, 1] with extrapolate, the
// end slope is continued; otherwise f is clamped (a NaN f reads entry 0). With interpolate,
// neighbouring entries are blended linearly; without, the entry below f is taken.
float4 rgb_ramp_lookup(std::span<const float4> table, float f, bool interpolate, bool extrapolate);
float float_ramp_lookup(std::span<const float> table, float f, bool interpolate, bool extrapolate);

// ColorRamp.interpolation; Cycles interpolates the baked table for every mode but CONSTANT.
enum class ColorRampInterpolation { EASE, CARDINAL, LINEAR, B_SPLINE, CONSTANT };
bool parse_color_ramp_interpolation(std::string_view id, ColorRampInterpolation* out);
bool color_ramp_interpolates(ColorRampInterpolation interpolation);

// Color Ramp node (ShaderNodeValToRGB): rgb = Color output, w = Alpha output. The table holds
// the ramp evaluated at i / (size - 1) (see bake_color_ramp).
float4 color_ramp_node(std::span<const float4> table, float fac, bool interpolate);

// CurveMapping.extend: Cycles extrapolates the table's end slopes only for EXTRAPOLATED.
enum class CurveExtend { HORIZONTAL, EXTRAPOLATED };
bool parse_curve_extend(std::string_view id, CurveExtend* out);

// RGB Curves (ShaderNodeRGBCurve) and Vector Curves (ShaderNodeVectorCurve): each channel c of
// the input is looked up at (c - min_x) / (max_x - min_x) in the x, y, z of the table (always
// interpolated), and the result mixed with the input by fac: (1 - fac) * in + fac * curve.
float3 rgb_curves_node(std::span<const float4> table, float min_x, float max_x, bool extrapolate,
                       float fac, float3 color);
float3 vector_curves_node(std::span<const float4> table, float min_x, float max_x, bool extrapolate,
                          float fac, float3 vector);
// Float Curve (ShaderNodeFloatCurve), the same over a float table.
float float_curve_node(std::span<const float> table, float min_x, float max_x, bool extrapolate,
                       float fac, float value);

// Baking as Blender's Cycles exporter does (intern/cycles/blender/util.h), for callers that
// hold a ramp or curve evaluator. A ramp samples [0, 1]; curves sample [min_x, max_x], which is
// the smallest first-point x and the largest last-point x over the curves involved (R, G, B and
// the combined C curve for RGB Curves; X, Y, Z for Vector Curves; the one curve for Float
// Curve). RGB Curves bake channel k as curve_k(curve_C(x)): the combined curve first.
std::vector<float4> bake_color_ramp(const std::function<float4(float)>& ramp,
                                    int size = kRampTableSize);
std::vector<float4> bake_rgb_curves(const std::function<float(int curve, float x)>& curve,
                                    float min_x, float max_x, int size = kRampTableSize);
std::vector<float4> bake_vector_curves(const std::function<float(int curve, float x)>& curve,
                                       float min_x, float max_x, int size = kRampTableSize);
std::vector<float> bake_float_curve(const std::function<float(float x)>& curve, float min_x,
                                    float max_x, int size = kRampTableSize);

}  // namespace glint::render::shader
