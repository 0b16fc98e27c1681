// Blender's CONVERTER shader nodes as pure functions giving Cycles 3.4's values: Math, Vector
// Math, Map Range, Clamp, Separate/Combine Color (RGB, HSV, HSL) and the legacy Separate/
// Combine RGB, HSV, XYZ nodes, Blackbody, Wavelength, and Cycles' implicit socket conversions.
// (Color Ramp, RGB to BW and the curve nodes live in color_nodes.h.)
//
// The arithmetic mirrors Cycles' SVM kernel (intern/cycles/kernel/svm/math_util.h, math.h,
// map_range.h, clamp.h, color_util.h, blackbody.h, wavelength.h) in single precision, with
// its NaN-avoiding "safe" operations. Enums are named after Blender's Python enum
// identifiers; each has a parse_* function taking that identifier.
#pragma once

#include <string_view>

#include "render/shader/float3.h"

namespace glint::render::shader {

// ---- Math ----------------------------------------------------------------------------------

// ShaderNodeMath.operation, in Blender 3.4's order.
enum class MathOp {
    ADD,
    SUBTRACT,
    MULTIPLY,
    DIVIDE,
    MULTIPLY_ADD,
    POWER,
    LOGARITHM,
    SQRT,
    INVERSE_SQRT,
    ABSOLUTE,
    EXPONENT,
    MINIMUM,
    MAXIMUM,
    LESS_THAN,
    GREATER_THAN,
    SIGN,
    COMPARE,
    SMOOTH_MIN,
    SMOOTH_MAX,
    ROUND,
    FLOOR,
    CEIL,
    TRUNC,
    FRACT,
    MODULO,
    WRAP,
    SNAP,
    PINGPONG,
    SINE,
    COSINE,
    TANGENT,
    ARCSINE,
    ARCCOSINE,
    ARCTANGENT,
    ARCTAN2,
    SINH,
    COSH,
    TANH,
    RADIANS,
    DEGREES,
};
bool parse_math_op(std::string_view id, MathOp* out);

// The operation on the node's three inputs (Cycles' svm_math). DIVIDE, POWER, LOGARITHM,
// SQRT, INVERSE_SQRT, MODULO (C fmod, sign of a), SNAP, WRAP, PINGPONG, ARCSINE and ARCCOSINE
// are Cycles' safe variants: 0 (or the clamped argument) where the plain one is undefined.
float math_op(MathOp op, float a, float b, float c);
// The Math node: math_op, then clamped to [0, 1] with use_clamp (a NaN becomes 0).
float math_node(MathOp op, float a, float b, float c, bool use_clamp);

// ---- Vector Math -----------------------------------------------------------------------------

// ShaderNodeVectorMath.operation, in Blender 3.4's order.
enum class VectorMathOp {
    ADD,
    SUBTRACT,
    MULTIPLY,
    DIVIDE,
    MULTIPLY_ADD,
    CROSS_PRODUCT,
    PROJECT,
    REFLECT,
    REFRACT,
    FACEFORWARD,
    DOT_PRODUCT,
    DISTANCE,
    LENGTH,
    SCALE,
    NORMALIZE,
    ABSOLUTE,
    MINIMUM,
    MAXIMUM,
    FLOOR,
    CEIL,
    FRACTION,
    MODULO,
    WRAP,
    SNAP,
    SINE,
    COSINE,
    TANGENT,
};
bool parse_vector_math_op(std::string_view id, VectorMathOp* out);
// True for DOT_PRODUCT, DISTANCE and LENGTH, whose result is the Value output.
bool vector_math_op_gives_value(VectorMathOp op);

struct VectorMathResult {
    float3 vector;       // the Vector output; zero for the value operations
    float value = 0.0f;  // the Value output; zero for the vector operations
};
// Inputs as the node's sockets: a = Vector, b = Vector_001, c = Vector_002 (MULTIPLY_ADD's
// addend, WRAP's min, FACEFORWARD's reference), scale = Scale (SCALE's factor, REFRACT's IOR).
// REFRACT normalizes b (a zero b gives NaN, as in Cycles); REFLECT and PROJECT use b as given.
VectorMathResult vector_math_node(VectorMathOp op, float3 a, float3 b, float3 c, float scale);

// ---- Map Range, Clamp ------------------------------------------------------------------------

// ShaderNodeMapRange.interpolation_type and .data_type.
enum class MapRangeInterpolation { LINEAR, STEPPED, SMOOTHSTEP, SMOOTHERSTEP };
bool parse_map_range_interpolation(std::string_view id, MapRangeInterpolation* out);
enum class MapRangeDataType { FLOAT, FLOAT_VECTOR };
bool parse_map_range_data_type(std::string_view id, MapRangeDataType* out);

// Float Map Range. An empty source range (from_min == from_max) gives 0. With clamp (for
// every interpolation, as Cycles appends a range Clamp node) the result is clamped between
// to_min and to_max, whichever order they come in.
float map_range_node(MapRangeInterpolation type, float value, float from_min, float from_max,
                     float to_min, float to_max, float steps, bool clamp);
// Vector Map Range, per component; an empty source range maps to to_min. clamp is honoured for
// LINEAR and STEPPED only (Cycles ignores it for the smooth ones).
float3 map_range_vector_node(MapRangeInterpolation type, float3 value, float3 from_min,
                             float3 from_max, float3 to_min, float3 to_max, float3 steps,
                             bool clamp);

// ShaderNodeClamp.clamp_type. RANGE swaps min and max when min > max; MINMAX does not (the
// result is then max).
enum class ClampType { MINMAX, RANGE };
bool parse_clamp_type(std::string_view id, ClampType* out);
float clamp_node(ClampType type, float value, float min, float max);

// ---- Separate / Combine --------------------------------------------------------------------

// ShaderNodeSeparateColor.mode / ShaderNodeCombineColor.mode.
enum class ColorMode { RGB, HSV, HSL };
bool parse_color_mode(std::string_view id, ColorMode* out);
// Separate Color: the three outputs (Red, Green, Blue / Hue, Saturation, Value / Hue,
// Saturation, Lightness) as x, y, z.
float3 separate_color_node(ColorMode mode, float3 color);
// Combine Color: the Color output from the three inputs.
float3 combine_color_node(ColorMode mode, float x, float y, float z);

// Legacy nodes: Separate/Combine HSV, RGB and XYZ (outputs as x, y, z).
float3 separate_hsv_node(float3 color);
float3 combine_hsv_node(float h, float s, float v);
inline float3 separate_rgb_node(float3 color) { return color; }
inline float3 combine_rgb_node(float r, float g, float b) { return {r, g, b}; }
inline float3 separate_xyz_node(float3 vector) { return vector; }
inline float3 combine_xyz_node(float x, float y, float z) { return {x, y, z}; }

// ---- Implicit conversions ------------------------------------------------------------------

// Cycles' conversions between socket types: a color becomes a float by its luminance (the
// RGB to BW node, color_nodes.h), a vector by the average of its components, a float becomes
// a color or vector (f, f, f).
float vector_to_float(float3 v);
inline float3 float_to_float3(float f) { return float3(f); }

// ---- Blackbody, Wavelength -------------------------------------------------------------------

// Cycles' Rec.709 fit of a black body's color at temperature kelvin (blackbody table of
// kernel/tables.h): piecewise a/T + bT + c for red and green and a cubic for blue, constant
// below 800 K and from 12000 K on. Not clamped: some components are negative.
float3 blackbody_rec709(float kelvin);
// Blackbody node: blackbody_rec709 clamped to >= 0 (scene linear is Rec.709 in Blender's
// default configuration, where Cycles applies no further transform).
float3 blackbody_node(float kelvin);

// A 3x3 matrix by rows.
struct ColorMatrix {
    float3 r, g, b;
};
// Cycles' XYZ -> scene linear matrix (film xyz_to_r/g/b) for Blender 3.4's default
// OpenColorIO configuration, as solved from Cycles' Wavelength output
// (tests/shader/make_math_refs.py, group xyz_matrix). Close to the standard XYZ -> linear
// Rec.709 matrix; it differs in the 7th digit because Cycles composes it through ACES AP0.
inline constexpr ColorMatrix kCyclesXyzToRgb{
    {3.24045536f, -1.53713998f, -0.498532218f},
    {-0.969266281f, 1.87601032f, 0.0415556951f},
    {0.0556436033f, -0.204025263f, 1.05722453f},
};
// CIE 1931 colour matching functions (Cycles' 5 nm table from 380 nm) interpolated linearly
// at lambda_nm; zero outside [375, 780) nm (Cycles extrapolates the first interval down to
// 375 nm by truncating toward zero).
float3 wavelength_to_xyz(float lambda_nm);
// Wavelength node: xyz_to_rgb applied to wavelength_to_xyz, scaled by 1 / 2.52 and clamped to
// >= 0.
float3 wavelength_node(float lambda_nm, const ColorMatrix& xyz_to_rgb = kCyclesXyzToRgb);

}  // namespace glint::render::shader
