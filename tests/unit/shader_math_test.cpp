// The Cycles 3.4 shader node functions of render/shader (color_nodes, converter_nodes,
// vector_nodes): hand-computed values for the simple cases, and Cycles' own outputs for all
// node operations.
//
// The k*Refs tables of shader_math_refs.inc hold Cycles 3.4.1's outputs, produced by
// tests/shader/make_math_refs.py, which renders each case as one pixel of an Emission shader
// fed by the node, with the node's inputs read from face attributes so that Cycles runs its
// SVM kernel rather than its compile-time constant folding. They agree with these functions to
// about 1e-7 (Cycles' kernel contracts some products and sums into FMAs); the test allows 1e-5.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "render/shader/color_nodes.h"
#include "render/shader/converter_nodes.h"
#include "render/shader/vector_nodes.h"

namespace glint::render::shader {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// Relative tolerance rel, with an absolute floor for results near zero.
::testing::AssertionResult Near(float got, float want, float rel = 1e-5f) {
    const float tol = std::max(rel * std::fabs(want), 1e-6f);
    if (std::fabs(got - want) <= tol) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "got " << got << ", want " << want << " (off by " << std::fabs(got - want) << ")";
}

::testing::AssertionResult Near3(float3 got, float3 want, float rel = 1e-5f) {
    for (int i = 0; i < 3; ++i) {
        if (!Near(got[i], want[i], rel)) {
            return ::testing::AssertionFailure()
                   << "got (" << got.x << ", " << got.y << ", " << got.z << "), want (" << want.x
                   << ", " << want.y << ", " << want.z << "): component " << i;
        }
    }
    return ::testing::AssertionSuccess();
}

// ---- Parsers --------------------------------------------------------------------------------

// Every identifier of a Blender enum, in Blender's order, parses to the enumerator of that
// position; anything else is refused and leaves the output alone.
template <typename E, typename Parse>
void ExpectParses(Parse parse, std::initializer_list<std::string_view> ids) {
    int i = 0;
    for (std::string_view id : ids) {
        E e{};
        EXPECT_TRUE(parse(id, &e)) << id;
        EXPECT_EQ(static_cast<int>(e), i) << id;
        ++i;
    }
    E e = static_cast<E>(1);
    EXPECT_FALSE(parse("NOT_AN_IDENTIFIER", &e));
    EXPECT_FALSE(parse("", &e));
    EXPECT_EQ(static_cast<int>(e), 1);
}

TEST(ShaderMathParse, AllBlenderIdentifiers) {
    ExpectParses<MathOp>(
        parse_math_op,
        {"ADD",        "SUBTRACT",  "MULTIPLY",     "DIVIDE",     "MULTIPLY_ADD", "POWER",
         "LOGARITHM",  "SQRT",      "INVERSE_SQRT", "ABSOLUTE",   "EXPONENT",     "MINIMUM",
         "MAXIMUM",    "LESS_THAN", "GREATER_THAN", "SIGN",       "COMPARE",      "SMOOTH_MIN",
         "SMOOTH_MAX", "ROUND",     "FLOOR",        "CEIL",       "TRUNC",        "FRACT",
         "MODULO",     "WRAP",      "SNAP",         "PINGPONG",   "SINE",         "COSINE",
         "TANGENT",    "ARCSINE",   "ARCCOSINE",    "ARCTANGENT", "ARCTAN2",      "SINH",
         "COSH",       "TANH",      "RADIANS",      "DEGREES"});
    ExpectParses<VectorMathOp>(
        parse_vector_math_op,
        {"ADD",     "SUBTRACT", "MULTIPLY",  "DIVIDE",      "MULTIPLY_ADD", "CROSS_PRODUCT",
         "PROJECT", "REFLECT",  "REFRACT",   "FACEFORWARD", "DOT_PRODUCT",  "DISTANCE",
         "LENGTH",  "SCALE",    "NORMALIZE", "ABSOLUTE",    "MINIMUM",      "MAXIMUM",
         "FLOOR",   "CEIL",     "FRACTION",  "MODULO",      "WRAP",         "SNAP",
         "SINE",    "COSINE",   "TANGENT"});
    ExpectParses<MixBlend>(
        parse_mix_blend, {"MIX", "DARKEN", "MULTIPLY", "BURN", "LIGHTEN", "SCREEN", "DODGE", "ADD",
                          "OVERLAY", "SOFT_LIGHT", "LINEAR_LIGHT", "DIFFERENCE", "SUBTRACT",
                          "DIVIDE", "HUE", "SATURATION", "COLOR", "VALUE"});
    ExpectParses<MixDataType>(parse_mix_data_type, {"FLOAT", "VECTOR", "RGBA"});
    ExpectParses<MixFactorMode>(parse_mix_factor_mode, {"UNIFORM", "NON_UNIFORM"});
    ExpectParses<ColorRampInterpolation>(parse_color_ramp_interpolation,
                                         {"EASE", "CARDINAL", "LINEAR", "B_SPLINE", "CONSTANT"});
    ExpectParses<CurveExtend>(parse_curve_extend, {"HORIZONTAL", "EXTRAPOLATED"});
    ExpectParses<MapRangeInterpolation>(parse_map_range_interpolation,
                                        {"LINEAR", "STEPPED", "SMOOTHSTEP", "SMOOTHERSTEP"});
    ExpectParses<MapRangeDataType>(parse_map_range_data_type, {"FLOAT", "FLOAT_VECTOR"});
    ExpectParses<ClampType>(parse_clamp_type, {"MINMAX", "RANGE"});
    ExpectParses<ColorMode>(parse_color_mode, {"RGB", "HSV", "HSL"});
    ExpectParses<MappingType>(parse_mapping_type, {"POINT", "TEXTURE", "VECTOR", "NORMAL"});
    ExpectParses<VectorRotateType>(parse_vector_rotate_type,
                                   {"AXIS_ANGLE", "X_AXIS", "Y_AXIS", "Z_AXIS", "EULER_XYZ"});
}

TEST(ShaderMathParse, IdentifiersAreCaseSensitive) {
    MathOp op{};
    EXPECT_FALSE(parse_math_op("add", &op));
    MixBlend blend{};
    EXPECT_FALSE(parse_mix_blend("Mix", &blend));
}

// ---- Math, by hand ----------------------------------------------------------------------------

TEST(ShaderMath, SafeOperations) {
    EXPECT_EQ(math_op(MathOp::ADD, 1.0f, 2.0f, 0.0f), 3.0f);
    EXPECT_EQ(math_op(MathOp::DIVIDE, 1.0f, 0.0f, 0.0f), 0.0f);
    EXPECT_EQ(math_op(MathOp::POWER, -8.0f, 1.0f / 3.0f, 0.0f), 0.0f);
    EXPECT_EQ(math_op(MathOp::POWER, -2.0f, 3.0f, 0.0f), -8.0f);
    EXPECT_EQ(math_op(MathOp::POWER, 0.0f, 0.0f, 0.0f), 1.0f);
    EXPECT_TRUE(Near(math_op(MathOp::LOGARITHM, 8.0f, 2.0f, 0.0f), 3.0f));
    EXPECT_EQ(math_op(MathOp::LOGARITHM, -8.0f, 2.0f, 0.0f), 0.0f);
    EXPECT_EQ(math_op(MathOp::LOGARITHM, 8.0f, 1.0f, 0.0f), 0.0f);
    EXPECT_EQ(math_op(MathOp::SQRT, -4.0f, 0.0f, 0.0f), 0.0f);
    EXPECT_EQ(math_op(MathOp::INVERSE_SQRT, 4.0f, 0.0f, 0.0f), 0.5f);
    EXPECT_EQ(math_op(MathOp::INVERSE_SQRT, 0.0f, 0.0f, 0.0f), 0.0f);
    EXPECT_EQ(math_op(MathOp::ARCSINE, 2.0f, 0.0f, 0.0f), std::asin(1.0f));
    EXPECT_EQ(math_op(MathOp::ARCCOSINE, -3.0f, 0.0f, 0.0f), std::acos(-1.0f));
}

TEST(ShaderMath, RoundingAndPeriodicOperations) {
    // MODULO is C's fmod: the sign of the dividend.
    EXPECT_EQ(math_op(MathOp::MODULO, -7.0f, 3.0f, 0.0f), -1.0f);
    EXPECT_EQ(math_op(MathOp::MODULO, 5.0f, 0.0f, 0.0f), 0.0f);
    EXPECT_EQ(math_op(MathOp::SNAP, 7.3f, 2.0f, 0.0f), 6.0f);
    EXPECT_EQ(math_op(MathOp::SNAP, 7.3f, 0.0f, 0.0f), 0.0f);
    EXPECT_EQ(math_op(MathOp::WRAP, 5.5f, 2.0f, 0.0f), 1.5f);  // b = max, c = min
    EXPECT_EQ(math_op(MathOp::WRAP, 5.5f, 2.0f, 2.0f), 2.0f);  // empty range gives min
    EXPECT_EQ(math_op(MathOp::PINGPONG, 5.5f, 2.0f, 0.0f), 1.5f);
    EXPECT_EQ(math_op(MathOp::PINGPONG, 5.5f, 0.0f, 0.0f), 0.0f);
    EXPECT_EQ(math_op(MathOp::TRUNC, -2.7f, 0.0f, 0.0f), -2.0f);
    EXPECT_EQ(math_op(MathOp::ROUND, -2.5f, 0.0f, 0.0f), -2.0f);
    EXPECT_EQ(math_op(MathOp::ROUND, 2.5f, 0.0f, 0.0f), 3.0f);
    EXPECT_EQ(math_op(MathOp::FRACT, -0.25f, 0.0f, 0.0f), 0.75f);
    EXPECT_EQ(math_op(MathOp::SIGN, 0.0f, 0.0f, 0.0f), 0.0f);
    EXPECT_EQ(math_op(MathOp::SIGN, -3.0f, 0.0f, 0.0f), -1.0f);
}

TEST(ShaderMath, ComparisonsAndSmoothMinMax) {
    EXPECT_EQ(math_op(MathOp::COMPARE, 1.0f, 1.05f, 0.1f), 1.0f);
    EXPECT_EQ(math_op(MathOp::COMPARE, 1.0f, 1.5f, 0.1f), 0.0f);
    EXPECT_EQ(math_op(MathOp::COMPARE, 1.0f, 1.0f, -1.0f), 1.0f);
    EXPECT_EQ(math_op(MathOp::LESS_THAN, 1.0f, 2.0f, 0.0f), 1.0f);
    EXPECT_EQ(math_op(MathOp::GREATER_THAN, 1.0f, 2.0f, 0.0f), 0.0f);
    EXPECT_EQ(math_op(MathOp::SMOOTH_MIN, 1.0f, 3.0f, 0.0f), 1.0f);
    EXPECT_TRUE(Near(math_op(MathOp::SMOOTH_MIN, 0.0f, 0.0f, 1.0f), -1.0f / 6.0f));
    EXPECT_TRUE(Near(math_op(MathOp::SMOOTH_MAX, 0.0f, 0.0f, 1.0f), 1.0f / 6.0f));
    EXPECT_EQ(math_op(MathOp::SMOOTH_MIN, 0.0f, 5.0f, 1.0f), 0.0f);  // beyond the blend
    EXPECT_TRUE(Near(math_op(MathOp::RADIANS, 180.0f, 0.0f, 0.0f), kPi));
    EXPECT_TRUE(Near(math_op(MathOp::DEGREES, kPi, 0.0f, 0.0f), 180.0f));
}

TEST(ShaderMath, NodeClampIncludingNaN) {
    EXPECT_EQ(math_node(MathOp::ADD, 0.7f, 0.6f, 0.0f, true), 1.0f);
    EXPECT_EQ(math_node(MathOp::ADD, 0.7f, 0.6f, 0.0f, false), 0.7f + 0.6f);
    EXPECT_EQ(math_node(MathOp::SUBTRACT, 0.2f, 0.6f, 0.0f, true), 0.0f);
    EXPECT_EQ(math_node(MathOp::ADD, kInf, -kInf, 0.0f, true), 0.0f);
}

// ---- Vector Math, by hand ---------------------------------------------------------------------

TEST(ShaderVectorMath, ProductsAndValueOutputs) {
    const float3 x(1, 0, 0), y(0, 1, 0);
    EXPECT_EQ(vector_math_node(VectorMathOp::CROSS_PRODUCT, x, y, {}, 1.0f).vector,
              float3(0, 0, 1));
    const VectorMathResult d =
        vector_math_node(VectorMathOp::DOT_PRODUCT, {1, 2, 3}, {4, 5, 6}, {}, 1.0f);
    EXPECT_EQ(d.value, 32.0f);
    EXPECT_EQ(d.vector, float3(0.0f));
    EXPECT_EQ(vector_math_node(VectorMathOp::LENGTH, {3, 4, 0}, {}, {}, 1.0f).value, 5.0f);
    EXPECT_EQ(vector_math_node(VectorMathOp::DISTANCE, {1, 1, 1}, {4, 5, 1}, {}, 1.0f).value, 5.0f);
    const VectorMathResult s = vector_math_node(VectorMathOp::SCALE, {1, 2, 3}, {}, {}, 2.0f);
    EXPECT_EQ(s.vector, float3(2, 4, 6));
    EXPECT_EQ(s.value, 0.0f);
    EXPECT_TRUE(vector_math_op_gives_value(VectorMathOp::DISTANCE));
    EXPECT_FALSE(vector_math_op_gives_value(VectorMathOp::NORMALIZE));
}

TEST(ShaderVectorMath, GeometricOperations) {
    EXPECT_EQ(vector_math_node(VectorMathOp::NORMALIZE, {0, 0, 0}, {}, {}, 1.0f).vector,
              float3(0.0f));
    EXPECT_EQ(vector_math_node(VectorMathOp::PROJECT, {1, 2, 3}, {0, 0, 0}, {}, 1.0f).vector,
              float3(0.0f));
    EXPECT_EQ(vector_math_node(VectorMathOp::PROJECT, {1, 2, 3}, {0, 2, 0}, {}, 1.0f).vector,
              float3(0, 2, 0));
    // REFLECT normalizes the normal.
    EXPECT_EQ(vector_math_node(VectorMathOp::REFLECT, {1, -1, 0}, {0, 2, 0}, {}, 1.0f).vector,
              float3(1, 1, 0));
    // REFRACT at eta 1 goes straight through; past the critical angle it gives zero.
    EXPECT_TRUE(
        Near3(vector_math_node(VectorMathOp::REFRACT, {0.6f, -0.8f, 0}, {0, 1, 0}, {}, 1.0f).vector,
              {0.6f, -0.8f, 0}));
    EXPECT_EQ(vector_math_node(VectorMathOp::REFRACT, {0.8f, -0.6f, 0}, {0, 1, 0}, {}, 1.5f).vector,
              float3(0.0f));
    EXPECT_TRUE(std::isnan(
        vector_math_node(VectorMathOp::REFRACT, {1, 0, 0}, {0, 0, 0}, {}, 1.5f).vector.x));
    EXPECT_EQ(
        vector_math_node(VectorMathOp::FACEFORWARD, {1, 2, 3}, {0, 0, 1}, {0, 0, -1}, 1.0f).vector,
        float3(1, 2, 3));
    EXPECT_EQ(
        vector_math_node(VectorMathOp::FACEFORWARD, {1, 2, 3}, {0, 0, 1}, {0, 0, 1}, 1.0f).vector,
        float3(-1, -2, -3));
}

TEST(ShaderVectorMath, ComponentwiseOperations) {
    EXPECT_EQ(vector_math_node(VectorMathOp::DIVIDE, {1, 2, 3}, {2, 0, -3}, {}, 1.0f).vector,
              float3(0.5f, 0, -1));
    EXPECT_EQ(vector_math_node(VectorMathOp::MODULO, {-7, 7, 1}, {3, 3, 0}, {}, 1.0f).vector,
              float3(-1, 1, 0));
    EXPECT_EQ(vector_math_node(VectorMathOp::SNAP, {7.3f, -0.5f, 1}, {2, 1, 0}, {}, 1.0f).vector,
              float3(6, -1, 0));
    EXPECT_EQ(
        vector_math_node(VectorMathOp::WRAP, {5.5f, -0.5f, 3}, {2, 1, 1}, {0, 0, 1}, 1.0f).vector,
        float3(1.5f, 0.5f, 1));
    EXPECT_EQ(
        vector_math_node(VectorMathOp::MULTIPLY_ADD, {1, 2, 3}, {2, 2, 2}, {1, 0, -1}, 1.0f).vector,
        float3(3, 4, 5));
    EXPECT_EQ(vector_math_node(VectorMathOp::FRACTION, {-0.25f, 1.5f, 2}, {}, {}, 1.0f).vector,
              float3(0.75f, 0.5f, 0));
}

// ---- Color, by hand ---------------------------------------------------------------------------

TEST(ShaderColor, MixFactorsAndClamps) {
    const float3 black(0.0f), white(1.0f), grey(0.25f);
    EXPECT_EQ(mix_blend(MixBlend::MIX, 0.25f, black, white), grey);
    EXPECT_EQ(mix_rgb_node(MixBlend::MIX, 2.0f, black, white, false), white);  // Fac clamped
    EXPECT_EQ(mix_color_node(MixBlend::MIX, 2.0f, black, white, false, false), float3(2.0f));
    EXPECT_EQ(mix_color_node(MixBlend::MIX, 2.0f, black, white, false, true), white);
    EXPECT_EQ(mix_color_node(MixBlend::ADD, 1.0f, white, white, true, true), white);
    EXPECT_EQ(mix_color_node(MixBlend::ADD, 1.0f, white, white, true, false), float3(2.0f));
    EXPECT_EQ(mix_float_node(-1.0f, 1.0f, 3.0f, false), -1.0f);
    EXPECT_EQ(mix_float_node(-1.0f, 1.0f, 3.0f, true), 1.0f);
    EXPECT_EQ(mix_vector_non_uniform_node({0, 0.5f, 2}, black, white, true), float3(0, 0.5f, 1));
    // DIVIDE leaves a channel alone where the divisor is zero.
    EXPECT_EQ(mix_blend(MixBlend::DIVIDE, 1.0f, {0.5f, 0.5f, 0.5f}, {0.5f, 0.0f, 2.0f}),
              float3(1.0f, 0.5f, 0.25f));
    // HUE with a grey second color changes nothing.
    EXPECT_EQ(mix_blend(MixBlend::HUE, 1.0f, {0.2f, 0.4f, 0.9f}, grey), float3(0.2f, 0.4f, 0.9f));
}

TEST(ShaderColor, HsvAndHslConversions) {
    EXPECT_EQ(rgb_to_hsv({1, 0, 0}), float3(0, 1, 1));
    EXPECT_EQ(rgb_to_hsv({0, 0, 0}), float3(0, 0, 0));
    EXPECT_TRUE(Near3(rgb_to_hsv({0, 0, 1}), {2.0f / 3.0f, 1, 1}));
    EXPECT_TRUE(Near3(hsv_to_rgb({1.0f / 3.0f, 1, 1}), {0, 1, 0}));
    EXPECT_EQ(hsv_to_rgb({1.0f, 1, 1}), float3(1, 0, 0));  // hue 1 wraps to 0
    EXPECT_EQ(hsv_to_rgb({0.7f, 0, 0.3f}), float3(0.3f));
    EXPECT_EQ(rgb_to_hsl({1, 0, 0}), float3(0, 1, 0.5f));
    EXPECT_TRUE(Near3(hsl_to_rgb({2.0f / 3.0f, 1, 0.5f}), {0, 0, 1}));
    const float3 c(0.2f, 0.6f, 0.9f);
    EXPECT_TRUE(Near3(hsv_to_rgb(rgb_to_hsv(c)), c));
    EXPECT_TRUE(Near3(hsl_to_rgb(rgb_to_hsl(c)), c));
}

TEST(ShaderColor, AdjustmentNodes) {
    const float3 c(0.2f, 0.6f, 0.9f);
    // Hue 0.5, saturation 1, value 1 is the identity.
    EXPECT_TRUE(Near3(hue_saturation_value_node(0.5f, 1.0f, 1.0f, 1.0f, c), c));
    EXPECT_EQ(hue_saturation_value_node(0.5f, 0.0f, 1.0f, 0.0f, c), c);
    EXPECT_EQ(gamma_node(c, 0.0f), float3(1.0f));
    EXPECT_EQ(gamma_node({-0.5f, 0.0f, 4.0f}, 0.5f), float3(-0.5f, 0.0f, 2.0f));
    EXPECT_TRUE(Near3(invert_node(1.0f, c), {0.8f, 0.4f, 0.1f}));
    EXPECT_EQ(invert_node(0.0f, c), c);
    EXPECT_EQ(bright_contrast_node(c, 0.0f, 0.0f), c);
    EXPECT_EQ(bright_contrast_node(c, -1.0f, 0.0f), float3(0.0f));  // clamped at zero
    EXPECT_TRUE(Near(rgb_to_bw_node({1, 1, 1}), 1.0f));
    EXPECT_EQ(rgb_to_bw_node({1, 2, 3}, {1, 0, 0}), 1.0f);
    EXPECT_EQ(vector_to_float({1, 2, 6}), 3.0f);
}

// The luminance weights are the Y row of the inverse of the XYZ matrix: both come from Cycles
// and were measured independently (RGB to BW of the unit colors; the Wavelength node).
TEST(ShaderColor, LuminanceMatchesXyzMatrix) {
    const ColorMatrix& m = kCyclesXyzToRgb;
    const double a = m.r.x, b = m.r.y, c = m.r.z, d = m.g.x, e = m.g.y, f = m.g.z, g = m.b.x,
                 h = m.b.y, i = m.b.z;
    const double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
    // Row 1 of the inverse (the Y row), by cofactors.
    const double y0 = -(d * i - f * g) / det, y1 = (a * i - c * g) / det,
                 y2 = -(a * f - c * d) / det;
    EXPECT_NEAR(y0, kCyclesRgbToY.x, 2e-6);
    EXPECT_NEAR(y1, kCyclesRgbToY.y, 2e-6);
    EXPECT_NEAR(y2, kCyclesRgbToY.z, 2e-6);
}

// ---- Ramps and curves, by hand ----------------------------------------------------------------

TEST(ShaderRamp, LookupInterpolationClampingAndExtrapolation) {
    const std::vector<float4> t = {{0, 0, 0, 1}, {1, 2, 3, 0.5f}, {3, 3, 3, 0}};
    const float4 a = rgb_ramp_lookup(t, 0.25f, true, false);
    EXPECT_EQ(a.x, 0.5f);
    EXPECT_EQ(a.w, 0.75f);
    EXPECT_EQ(rgb_ramp_lookup(t, 0.25f, false, false).x, 0.0f);
    EXPECT_EQ(rgb_ramp_lookup(t, 0.75f, false, false).x, 1.0f);
    EXPECT_EQ(rgb_ramp_lookup(t, 1.0f, true, false).x, 3.0f);
    EXPECT_EQ(rgb_ramp_lookup(t, 7.0f, true, false).x, 3.0f);
    EXPECT_EQ(rgb_ramp_lookup(t, -7.0f, true, false).x, 0.0f);
    EXPECT_EQ(rgb_ramp_lookup(t, kNaN, true, false).x, 0.0f);
    // The end slope continued: 3 + (3 - 1) * 0.5 * 2 and 0 + (0 - 1) * 0.5 * 2.
    EXPECT_EQ(rgb_ramp_lookup(t, 1.5f, true, true).x, 5.0f);
    EXPECT_EQ(rgb_ramp_lookup(t, -0.5f, true, true).x, -1.0f);
    const std::vector<float> ft = {0.0f, 1.0f, 3.0f};
    EXPECT_EQ(float_ramp_lookup(ft, 0.75f, true, false), 2.0f);
    EXPECT_EQ(float_ramp_lookup(ft, 1.5f, true, true), 5.0f);
    const float4 c =
        color_ramp_node(t, 0.5f, color_ramp_interpolates(ColorRampInterpolation::EASE));
    EXPECT_EQ(c.x, 1.0f);
    EXPECT_FALSE(color_ramp_interpolates(ColorRampInterpolation::CONSTANT));
}

TEST(ShaderRamp, CurvesBakeCombinedCurveFirstAndMixByFac) {
    // R doubles, G negates, B passes; the combined curve adds 1.
    auto curve = [](int k, float x) {
        switch (k) {
            case 0:
                return 2.0f * x;
            case 1:
                return -x;
            case 2:
                return x;
            default:
                return x + 1.0f;
        }
    };
    const std::vector<float4> t = bake_rgb_curves(curve, 0.0f, 2.0f, 3);
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[1].x, 4.0f);  // R(C(1)) = 2 * 2
    EXPECT_EQ(t[1].y, -2.0f);
    EXPECT_EQ(t[2].z, 3.0f);
    EXPECT_EQ(rgb_curves_node(t, 0.0f, 2.0f, false, 1.0f, {1, 1, 1}), float3(4, -2, 2));
    EXPECT_EQ(rgb_curves_node(t, 0.0f, 2.0f, false, 0.5f, {1, 1, 1}), float3(2.5f, -0.5f, 1.5f));
    const std::vector<float4> v = bake_vector_curves(curve, -1.0f, 1.0f, 3);
    EXPECT_EQ(vector_curves_node(v, -1.0f, 1.0f, true, 1.0f, {0.5f, 3.0f, -1.0f}),
              float3(1.0f, -3.0f, -1.0f));
    const std::vector<float> f = bake_float_curve([](float x) { return x * x; }, 0.0f, 2.0f, 3);
    EXPECT_EQ(f[2], 4.0f);
    EXPECT_EQ(float_curve_node(f, 0.0f, 2.0f, false, 1.0f, 1.5f), 2.5f);
    EXPECT_EQ(float_curve_node(f, 0.0f, 2.0f, false, 0.0f, 1.5f), 1.5f);
    const std::vector<float4> r = bake_color_ramp(
        [](float x) {
            return float4{x, 1 - x, 0, 1};
        },
        5);
    EXPECT_EQ(r[1].x, 0.25f);
    EXPECT_EQ(r[4].y, 0.0f);
}

// ---- Map Range, Clamp, Separate/Combine, by hand ------------------------------------------------

TEST(ShaderConverter, MapRangeAndClamp) {
    using I = MapRangeInterpolation;
    EXPECT_EQ(map_range_node(I::LINEAR, 0.5f, 0, 1, 10, 20, 4, false), 15.0f);
    EXPECT_EQ(map_range_node(I::LINEAR, 2.0f, 0, 1, 10, 20, 4, false), 30.0f);
    EXPECT_EQ(map_range_node(I::LINEAR, 2.0f, 0, 1, 10, 20, 4, true), 20.0f);
    EXPECT_EQ(map_range_node(I::LINEAR, 2.0f, 0, 1, 20, 10, 4, true), 10.0f);
    EXPECT_EQ(map_range_node(I::LINEAR, 0.5f, 1, 1, 10, 20, 4, false), 0.0f);
    EXPECT_EQ(map_range_node(I::STEPPED, 0.6f, 0, 1, 0, 1, 4, false), 0.75f);
    EXPECT_EQ(map_range_node(I::SMOOTHSTEP, 0.5f, 0, 1, 0, 1, 4, false), 0.5f);
    EXPECT_EQ(map_range_node(I::SMOOTHERSTEP, 0.5f, 0, 1, 0, 1, 4, false), 0.5f);
    EXPECT_EQ(map_range_vector_node(I::LINEAR, {0.5f, 1, 2}, {0, 1, 0}, {1, 1, 1}, {0, 5, 0},
                                    {2, 6, 1}, {4, 4, 4}, true),
              float3(1, 5, 1));
    EXPECT_EQ(clamp_node(ClampType::MINMAX, 0.5f, 0.8f, 0.2f), 0.2f);
    EXPECT_EQ(clamp_node(ClampType::RANGE, 0.5f, 0.8f, 0.2f), 0.5f);
    EXPECT_EQ(clamp_node(ClampType::RANGE, 0.9f, 0.8f, 0.2f), 0.8f);
}

TEST(ShaderConverter, SeparateCombine) {
    const float3 c(0.2f, 0.6f, 0.9f);
    EXPECT_EQ(separate_color_node(ColorMode::RGB, c), c);
    EXPECT_EQ(separate_color_node(ColorMode::HSV, c), rgb_to_hsv(c));
    EXPECT_EQ(separate_color_node(ColorMode::HSL, c), rgb_to_hsl(c));
    EXPECT_EQ(combine_color_node(ColorMode::HSV, 0.1f, 0.5f, 0.7f), hsv_to_rgb({0.1f, 0.5f, 0.7f}));
    EXPECT_EQ(combine_color_node(ColorMode::HSL, 0.1f, 0.5f, 0.7f), hsl_to_rgb({0.1f, 0.5f, 0.7f}));
    EXPECT_EQ(separate_hsv_node(c), rgb_to_hsv(c));
    EXPECT_EQ(combine_hsv_node(0.1f, 0.5f, 0.7f), hsv_to_rgb({0.1f, 0.5f, 0.7f}));
    EXPECT_EQ(combine_xyz_node(1, 2, 3), float3(1, 2, 3));
    EXPECT_EQ(separate_rgb_node(c), c);
}

TEST(ShaderConverter, BlackbodyAndWavelengthEnds) {
    EXPECT_EQ(blackbody_rec709(12000.0f), blackbody_rec709(50000.0f));
    EXPECT_EQ(blackbody_node(100.0f), float3(blackbody_rec709(100.0f).x, 0.0f, 0.0f));
    EXPECT_TRUE(std::isnan(blackbody_rec709(kNaN).x));
    EXPECT_EQ(blackbody_node(kNaN), float3(0.0f));  // Cycles' max(NaN, 0) is 0
    EXPECT_EQ(wavelength_node(300.0f), float3(0.0f));
    EXPECT_EQ(wavelength_node(780.0f), float3(0.0f));
    EXPECT_EQ(wavelength_node(kNaN), float3(0.0f));
    EXPECT_EQ(wavelength_to_xyz(385.0f), float3(0.0022f, 0.0001f, 0.0105f));
    // Cycles truncates toward zero, so 375..380 nm extrapolates the first interval.
    EXPECT_TRUE(Near3(wavelength_to_xyz(377.5f), {0.001f, -0.00005f, 0.0045f}));
    EXPECT_EQ(wavelength_to_xyz(375.0f), float3(0.0f));
}

// ---- Mapping, Vector Rotate, by hand ------------------------------------------------------------

TEST(ShaderVector, MappingTypes) {
    const float3 quarter_z(0, 0, kPi / 2);
    EXPECT_EQ(mapping_node(MappingType::POINT, {1, 2, 3}, {1, 1, 1}, {}, {2, 2, 2}),
              float3(3, 5, 7));
    EXPECT_TRUE(Near3(mapping_node(MappingType::VECTOR, {1, 0, 0}, {5, 5, 5}, quarter_z, {1, 1, 1}),
                      {0, 1, 0}));
    // TEXTURE undoes POINT.
    const float3 loc(0.3f, -1, 2), rot(0.4f, -0.2f, 1.1f), scale(2, 0.5f, -1);
    const float3 p = mapping_node(MappingType::POINT, {0.7f, 0.1f, -0.4f}, loc, rot, scale);
    EXPECT_TRUE(Near3(mapping_node(MappingType::TEXTURE, p, loc, rot, scale), {0.7f, 0.1f, -0.4f}));
    EXPECT_EQ(mapping_node(MappingType::TEXTURE, {1, 2, 3}, {}, {}, {0, 1, 1}), float3(0, 2, 3));
    EXPECT_TRUE(Near(len(mapping_node(MappingType::NORMAL, {1, 2, 3}, {}, rot, scale)), 1.0f));
}

TEST(ShaderVector, VectorRotateTypes) {
    using T = VectorRotateType;
    const float3 v(1, 0, 0), o(0.0f);
    EXPECT_TRUE(Near3(vector_rotate_node(T::Z_AXIS, v, o, {}, kPi / 2, {}, false), {0, 1, 0}));
    EXPECT_TRUE(Near3(vector_rotate_node(T::Z_AXIS, v, o, {}, kPi / 2, {}, true), {0, -1, 0}));
    EXPECT_TRUE(
        Near3(vector_rotate_node(T::AXIS_ANGLE, v, o, {0, 0, 2}, kPi / 2, {}, false), {0, 1, 0}));
    EXPECT_EQ(vector_rotate_node(T::AXIS_ANGLE, v, o, {0, 0, 0}, kPi / 2, {}, false), v);
    EXPECT_TRUE(
        Near3(vector_rotate_node(T::EULER_XYZ, v, o, {}, 0, {0, 0, kPi / 2}, false), {0, 1, 0}));
    EXPECT_TRUE(
        Near3(vector_rotate_node(T::X_AXIS, {1, 1, 0}, {1, 0, 0}, {}, kPi, {}, false), {1, -1, 0}));
    const float3 rot(0.3f, -0.7f, 1.2f), w(0.3f, -1.2f, 2.5f);
    const float3 there = vector_rotate_node(T::EULER_XYZ, w, {1, 2, 3}, {}, 0, rot, false);
    EXPECT_TRUE(Near3(vector_rotate_node(T::EULER_XYZ, there, {1, 2, 3}, {}, 0, rot, true), w));
}

// ---- Cycles' own values
// --------------------------------------------------------------------------

#include "unit/shader_math_refs.inc"  // the *Ref structs and k*Refs tables

template <typename E, typename Parse>
E Parsed(Parse parse, const char* id) {
    E e{};
    EXPECT_TRUE(parse(id, &e)) << id;
    return e;
}

TEST(ShaderCyclesRefs, Math) {
    for (const MathRef& r : kMathRefs) {
        SCOPED_TRACE(std::string(r.op) + " " + std::to_string(r.a) + " " + std::to_string(r.b) +
                     " " + std::to_string(r.c) + (r.clamp ? " clamp" : ""));
        const MathOp op = Parsed<MathOp>(parse_math_op, r.op);
        EXPECT_TRUE(Near(math_node(op, r.a, r.b, r.c, r.clamp), r.expected));
    }
}

TEST(ShaderCyclesRefs, VectorMath) {
    for (const VectorMathRef& r : kVectorMathRefs) {
        SCOPED_TRACE(std::string(r.op) + " scale " + std::to_string(r.scale));
        const VectorMathOp op = Parsed<VectorMathOp>(parse_vector_math_op, r.op);
        const VectorMathResult got = vector_math_node(op, r.a, r.b, r.c, r.scale);
        if (vector_math_op_gives_value(op)) {
            EXPECT_TRUE(Near(got.value, r.expected.x));
        } else {
            EXPECT_TRUE(Near3(got.vector, r.expected));
        }
    }
}

TEST(ShaderCyclesRefs, MixRgb) {
    for (const MixRgbRef& r : kMixRgbRefs) {
        SCOPED_TRACE(std::string(r.blend) + " fac " + std::to_string(r.fac) +
                     (r.clamp ? " clamp" : ""));
        const MixBlend b = Parsed<MixBlend>(parse_mix_blend, r.blend);
        EXPECT_TRUE(Near3(mix_rgb_node(b, r.fac, r.c1, r.c2, r.clamp), r.expected));
    }
}

TEST(ShaderCyclesRefs, MixColor) {
    for (const MixColorRef& r : kMixColorRefs) {
        SCOPED_TRACE(std::string(r.blend) + " fac " + std::to_string(r.fac) +
                     (r.clamp_factor ? " clamp_factor" : "") +
                     (r.clamp_result ? " clamp_result" : ""));
        const MixBlend b = Parsed<MixBlend>(parse_mix_blend, r.blend);
        EXPECT_TRUE(
            Near3(mix_color_node(b, r.fac, r.a, r.b, r.clamp_factor, r.clamp_result), r.expected));
    }
}

TEST(ShaderCyclesRefs, MixFloatAndVector) {
    for (const MixOtherRef& r : kMixOtherRefs) {
        const std::string kind = r.kind;
        SCOPED_TRACE(kind + (r.clamp_factor ? " clamp_factor" : ""));
        if (kind == "FLOAT") {
            EXPECT_TRUE(Near(mix_float_node(r.fac.x, r.a.x, r.b.x, r.clamp_factor), r.expected.x));
        } else if (kind == "VECTOR") {
            EXPECT_TRUE(Near3(mix_vector_node(r.fac.x, r.a, r.b, r.clamp_factor), r.expected));
        } else {
            EXPECT_TRUE(
                Near3(mix_vector_non_uniform_node(r.fac, r.a, r.b, r.clamp_factor), r.expected));
        }
    }
}

TEST(ShaderCyclesRefs, ColorAdjustments) {
    for (const HsvRef& r : kHsvRefs) {
        SCOPED_TRACE("hsv " + std::to_string(r.hue));
        EXPECT_TRUE(Near3(hue_saturation_value_node(r.hue, r.saturation, r.value, r.fac, r.color),
                          r.expected));
    }
    for (const BrightContrastRef& r : kBrightContrastRefs) {
        EXPECT_TRUE(Near3(bright_contrast_node(r.color, r.bright, r.contrast), r.expected));
    }
    for (const GammaRef& r : kGammaRefs) {
        EXPECT_TRUE(Near3(gamma_node(r.color, r.gamma), r.expected));
    }
    for (const InvertRef& r : kInvertRefs) {
        EXPECT_TRUE(Near3(invert_node(r.fac, r.color), r.expected));
    }
    for (const RgbToBwRef& r : kRgbToBwRefs) {
        EXPECT_TRUE(Near(rgb_to_bw_node(r.color), r.expected));
    }
}

TEST(ShaderCyclesRefs, SeparateCombine) {
    for (const SepCombRef& r : kSepCombRefs) {
        const std::string mode = r.mode, dir = r.direction;
        SCOPED_TRACE(mode + " " + dir);
        float3 got;
        if (mode == "LEGACY_HSV") {
            got = dir == "SEPARATE" ? separate_hsv_node(r.in)
                                    : combine_hsv_node(r.in.x, r.in.y, r.in.z);
        } else {
            const ColorMode m = Parsed<ColorMode>(parse_color_mode, r.mode);
            got = dir == "SEPARATE" ? separate_color_node(m, r.in)
                                    : combine_color_node(m, r.in.x, r.in.y, r.in.z);
        }
        EXPECT_TRUE(Near3(got, r.expected));
    }
}

TEST(ShaderCyclesRefs, MapRangeAndClamp) {
    for (const MapRangeRef& r : kMapRangeRefs) {
        SCOPED_TRACE(std::string(r.type) + " " + r.data_type + (r.clamp ? " clamp" : ""));
        const auto type = Parsed<MapRangeInterpolation>(parse_map_range_interpolation, r.type);
        const auto data = Parsed<MapRangeDataType>(parse_map_range_data_type, r.data_type);
        if (data == MapRangeDataType::FLOAT) {
            EXPECT_TRUE(Near(map_range_node(type, r.value.x, r.from_min.x, r.from_max.x, r.to_min.x,
                                            r.to_max.x, r.steps.x, r.clamp),
                             r.expected.x));
        } else {
            EXPECT_TRUE(Near3(map_range_vector_node(type, r.value, r.from_min, r.from_max, r.to_min,
                                                    r.to_max, r.steps, r.clamp),
                              r.expected));
        }
    }
    for (const ClampRef& r : kClampRefs) {
        SCOPED_TRACE(r.type);
        const ClampType t = Parsed<ClampType>(parse_clamp_type, r.type);
        EXPECT_TRUE(Near(clamp_node(t, r.value, r.min, r.max), r.expected));
    }
}

TEST(ShaderCyclesRefs, BlackbodyAndWavelength) {
    EXPECT_EQ(kCyclesXyzToRgb.r, kSolvedXyzToRgb[0]);
    EXPECT_EQ(kCyclesXyzToRgb.g, kSolvedXyzToRgb[1]);
    EXPECT_EQ(kCyclesXyzToRgb.b, kSolvedXyzToRgb[2]);
    for (const SpectrumRef& r : kBlackbodyRefs) {
        SCOPED_TRACE("blackbody " + std::to_string(r.x));
        EXPECT_TRUE(Near3(blackbody_node(r.x), r.expected));
    }
    for (const SpectrumRef& r : kWavelengthRefs) {
        SCOPED_TRACE("wavelength " + std::to_string(r.x));
        EXPECT_TRUE(Near3(wavelength_node(r.x), r.expected));
    }
}

TEST(ShaderCyclesRefs, MappingAndVectorRotate) {
    for (const MappingRef& r : kMappingRefs) {
        SCOPED_TRACE(r.type);
        const MappingType t = Parsed<MappingType>(parse_mapping_type, r.type);
        EXPECT_TRUE(Near3(mapping_node(t, r.vector, r.location, r.rotation, r.scale), r.expected));
    }
    for (const VectorRotateRef& r : kVectorRotateRefs) {
        SCOPED_TRACE(std::string(r.type) + (r.invert ? " invert" : ""));
        const VectorRotateType t = Parsed<VectorRotateType>(parse_vector_rotate_type, r.type);
        EXPECT_TRUE(
            Near3(vector_rotate_node(t, r.vector, r.center, r.axis, r.angle, r.rotation, r.invert),
                  r.expected));
    }
}

// The ramps and curves of make_math_refs.py, baked here from the straight lines they are made
// of (the script checks Blender's own tables are within 2e-7 of these).
std::vector<float4> LinearRamp() {
    const float4 a{0.1f, 0.2f, 0.9f, 0.5f}, b{0.9f, 0.6f, 0.1f, 1.0f};
    return bake_color_ramp(
        [&](float t) {
            return float4{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t,
                          a.w + (b.w - a.w) * t};
        },
        kRampTableSize);
}

std::vector<float4> ConstantRamp() {
    return bake_color_ramp(
        [](float t) {
            if (t < 0.41f) return float4{0.1f, 0.2f, 0.3f, 1.0f};
            if (t < 0.69f) return float4{0.5f, 0.6f, 0.7f, 0.8f};
            return float4{0.9f, 0.1f, 0.2f, 0.3f};
        },
        kRampTableSize);
}

TEST(ShaderCyclesRefs, RampsAndCurves) {
    const std::vector<float4> linear = LinearRamp(), constant = ConstantRamp();
    const std::vector<float4> rgb = bake_rgb_curves(
        [](int k, float x) {
            switch (k) {
                case 0:
                    return 0.5f * x;
                case 1:
                    return 1.0f - x;
                case 2:
                    return x;
                default:
                    return 0.1f + (x + 0.5f) / 1.5f * 0.8f;
            }
        },
        -0.5f, 1.0f);
    auto vector_curves = [](bool extrapolated) {
        return bake_vector_curves(
            [=](int k, float x) {
                if (k == 0) return (x - 1.0f) * 0.5f;
                if (k == 1) return x;
                const float z = 0.5f - (x + 1.0f);
                return extrapolated ? z : std::max(z, -1.0f);
            },
            -1.0f, 1.0f);
    };
    const std::vector<float4> vec_ext = vector_curves(true), vec_hor = vector_curves(false);
    const std::vector<float> flt =
        bake_float_curve([](float x) { return 1.0f - (x + 0.5f) / 2.5f; }, -0.5f, 2.0f);

    for (const RampRef& r : kRampRefs) {
        const std::string name = r.name, out = r.output;
        SCOPED_TRACE(name + " " + out + " fac " + std::to_string(r.fac));
        // Extrapolation multiplies the table's end slope by up to 255 * the overshoot, and
        // with it the last-bit differences between these tables and Blender's.
        const float rel = 1e-4f;
        if (name == "RAMP_LINEAR" || name == "RAMP_CONSTANT") {
            const float4 c = color_ramp_node(name == "RAMP_LINEAR" ? linear : constant, r.fac,
                                             name == "RAMP_LINEAR");
            if (out == "Color") {
                EXPECT_TRUE(Near3({c.x, c.y, c.z}, r.expected));
            } else {
                EXPECT_TRUE(Near(c.w, r.expected.x));
            }
        } else if (name == "RGB_CURVES") {
            EXPECT_TRUE(
                Near3(rgb_curves_node(rgb, -0.5f, 1.0f, true, r.fac, r.in), r.expected, rel));
        } else if (name == "VECTOR_CURVES_EXTRAPOLATED") {
            EXPECT_TRUE(Near3(vector_curves_node(vec_ext, -1.0f, 1.0f, true, r.fac, r.in),
                              r.expected, rel));
        } else if (name == "VECTOR_CURVES_HORIZONTAL") {
            EXPECT_TRUE(
                Near3(vector_curves_node(vec_hor, -1.0f, 1.0f, false, r.fac, r.in), r.expected));
        } else {
            EXPECT_TRUE(
                Near(float_curve_node(flt, -0.5f, 2.0f, true, r.fac, r.in.x), r.expected.x, rel));
        }
    }
}

}  // namespace
}  // namespace glint::render::shader
