// Cycles 3.4's converter node arithmetic (kernel/svm/math_util.h, math.h, map_range.h,
// clamp.h, sepcomb_*.h, color_util.h, blackbody.h, wavelength.h; util/math.h), restated in
// single precision.
#include "render/shader/converter_nodes.h"

#include "render/shader/enum_table.h"

#include <array>
#include <cfloat>
#include <cmath>
#include <utility>

#include "render/shader/color_nodes.h"

namespace glint::render::shader {
namespace {

constexpr float kPiF = 3.14159265358979323846f;

// Cycles' min/max/clamp: comparisons, so a NaN first argument yields the bound.
float cmin(float a, float b) { return a < b ? a : b; }
float cmax(float a, float b) { return a > b ? a : b; }
float cclamp(float a, float lo, float hi) { return cmin(cmax(a, lo), hi); }

float3 map3(float3 a, float (*fn)(float)) { return {fn(a.x), fn(a.y), fn(a.z)}; }
float3 floor3(float3 a) {
    return map3(a, [](float x) { return std::floor(x); });
}

float safe_divide(float a, float b) { return b != 0.0f ? a / b : 0.0f; }
float3 safe_divide(float3 a, float3 b) {
    return {safe_divide(a.x, b.x), safe_divide(a.y, b.y), safe_divide(a.z, b.z)};
}
float safe_modulo(float a, float b) { return b != 0.0f ? std::fmod(a, b) : 0.0f; }

// Whether b equals (float)(int)b as Cycles computes it: out of int range (and NaN) the x86
// conversion gives INT_MIN.
bool equals_its_int(float b) {
    if (std::fabs(b) < 2147483648.0f) return b == std::trunc(b);
    return b == -2147483648.0f;
}

float safe_pow(float a, float b) {
    if (a < 0.0f && !equals_its_int(b)) return 0.0f;
    return std::pow(a, b);
}

float safe_log(float a, float base) {
    if (a <= 0.0f || base <= 0.0f) return 0.0f;
    return safe_divide(std::log(a), std::log(base));
}

float wrap(float value, float max, float min) {
    const float range = max - min;
    return range != 0.0f ? value - range * std::floor((value - min) / range) : min;
}

float pingpong(float a, float b) {
    if (b == 0.0f) return 0.0f;
    const float x = (a - b) / (b * 2.0f);
    return std::fabs((x - std::floor(x)) * b * 2.0f - b);
}

float smooth_min(float a, float b, float k) {
    if (k == 0.0f) return std::fmin(a, b);
    const float h = std::fmax(k - std::fabs(a - b), 0.0f) / k;
    return std::fmin(a, b) - h * h * h * k * (1.0f / 6.0f);
}

float sign_or_zero(float f) {
    if (f == 0.0f) return 0.0f;
    return f < 0.0f ? -1.0f : 1.0f;
}

float smoothstep(float edge0, float edge1, float x) {
    if (x < edge0) return 0.0f;
    if (x >= edge1) return 1.0f;
    const float t = (x - edge0) / (edge1 - edge0);
    return (3.0f - 2.0f * t) * (t * t);
}

float smootherstep(float edge0, float edge1, float x) {
    const float t = cclamp(safe_divide(x - edge0, edge1 - edge0), 0.0f, 1.0f);
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

float3 normalize_unsafe(float3 a) { return a / len(a); }

float3 reflect(float3 incident, float3 normal) {
    const float3 n = normalize_unsafe(normal);
    return incident - (2.0f * n) * dot(incident, n);
}

float3 refract(float3 incident, float3 normal, float eta) {
    const float d = dot(normal, incident);
    const float k = 1.0f - eta * eta * (1.0f - d * d);
    if (k < 0.0f) return float3(0.0f);
    return eta * incident - (eta * d + std::sqrt(k)) * normal;
}

float3 project(float3 v, float3 onto) {
    const float l2 = dot(onto, onto);
    return l2 != 0.0f ? (dot(v, onto) / l2) * onto : float3(0.0f);
}


}  // namespace

// ---- Math ----------------------------------------------------------------------------------

bool parse_math_op(std::string_view id, MathOp* out) {
    using M = MathOp;
    static constexpr std::array<std::pair<std::string_view, M>, 40> kTable{{
        {"ADD", M::ADD},
        {"SUBTRACT", M::SUBTRACT},
        {"MULTIPLY", M::MULTIPLY},
        {"DIVIDE", M::DIVIDE},
        {"MULTIPLY_ADD", M::MULTIPLY_ADD},
        {"POWER", M::POWER},
        {"LOGARITHM", M::LOGARITHM},
        {"SQRT", M::SQRT},
        {"INVERSE_SQRT", M::INVERSE_SQRT},
        {"ABSOLUTE", M::ABSOLUTE},
        {"EXPONENT", M::EXPONENT},
        {"MINIMUM", M::MINIMUM},
        {"MAXIMUM", M::MAXIMUM},
        {"LESS_THAN", M::LESS_THAN},
        {"GREATER_THAN", M::GREATER_THAN},
        {"SIGN", M::SIGN},
        {"COMPARE", M::COMPARE},
        {"SMOOTH_MIN", M::SMOOTH_MIN},
        {"SMOOTH_MAX", M::SMOOTH_MAX},
        {"ROUND", M::ROUND},
        {"FLOOR", M::FLOOR},
        {"CEIL", M::CEIL},
        {"TRUNC", M::TRUNC},
        {"FRACT", M::FRACT},
        {"MODULO", M::MODULO},
        {"WRAP", M::WRAP},
        {"SNAP", M::SNAP},
        {"PINGPONG", M::PINGPONG},
        {"SINE", M::SINE},
        {"COSINE", M::COSINE},
        {"TANGENT", M::TANGENT},
        {"ARCSINE", M::ARCSINE},
        {"ARCCOSINE", M::ARCCOSINE},
        {"ARCTANGENT", M::ARCTANGENT},
        {"ARCTAN2", M::ARCTAN2},
        {"SINH", M::SINH},
        {"COSH", M::COSH},
        {"TANH", M::TANH},
        {"RADIANS", M::RADIANS},
        {"DEGREES", M::DEGREES},
    }};
    return parse_enum(id, kTable, out);
}

float math_op(MathOp op, float a, float b, float c) {
    switch (op) {
        case MathOp::ADD:
            return a + b;
        case MathOp::SUBTRACT:
            return a - b;
        case MathOp::MULTIPLY:
            return a * b;
        case MathOp::DIVIDE:
            return safe_divide(a, b);
        case MathOp::MULTIPLY_ADD:
            return a * b + c;
        case MathOp::POWER:
            return safe_pow(a, b);
        case MathOp::LOGARITHM:
            return safe_log(a, b);
        case MathOp::SQRT:
            return std::sqrt(cmax(a, 0.0f));
        case MathOp::INVERSE_SQRT:
            return a > 0.0f ? 1.0f / std::sqrt(a) : 0.0f;
        case MathOp::ABSOLUTE:
            return std::fabs(a);
        case MathOp::EXPONENT:
            return std::exp(a);
        case MathOp::MINIMUM:
            return std::fmin(a, b);
        case MathOp::MAXIMUM:
            return std::fmax(a, b);
        case MathOp::LESS_THAN:
            return a < b ? 1.0f : 0.0f;
        case MathOp::GREATER_THAN:
            return a > b ? 1.0f : 0.0f;
        case MathOp::SIGN:
            return sign_or_zero(a);
        case MathOp::COMPARE:
            return (a == b || std::fabs(a - b) <= std::fmax(c, FLT_EPSILON)) ? 1.0f : 0.0f;
        case MathOp::SMOOTH_MIN:
            return smooth_min(a, b, c);
        case MathOp::SMOOTH_MAX:
            return -smooth_min(-a, -b, c);
        case MathOp::ROUND:
            return std::floor(a + 0.5f);
        case MathOp::FLOOR:
            return std::floor(a);
        case MathOp::CEIL:
            return std::ceil(a);
        case MathOp::TRUNC:
            return a >= 0.0f ? std::floor(a) : std::ceil(a);
        case MathOp::FRACT:
            return a - std::floor(a);
        case MathOp::MODULO:
            return safe_modulo(a, b);
        case MathOp::WRAP:
            return wrap(a, b, c);
        case MathOp::SNAP:
            return std::floor(safe_divide(a, b)) * b;
        case MathOp::PINGPONG:
            return pingpong(a, b);
        case MathOp::SINE:
            return std::sin(a);
        case MathOp::COSINE:
            return std::cos(a);
        case MathOp::TANGENT:
            return std::tan(a);
        case MathOp::ARCSINE:
            return std::asin(cclamp(a, -1.0f, 1.0f));
        case MathOp::ARCCOSINE:
            return std::acos(cclamp(a, -1.0f, 1.0f));
        case MathOp::ARCTANGENT:
            return std::atan(a);
        case MathOp::ARCTAN2:
            return std::atan2(a, b);
        case MathOp::SINH:
            return std::sinh(a);
        case MathOp::COSH:
            return std::cosh(a);
        case MathOp::TANH:
            return std::tanh(a);
        case MathOp::RADIANS:
            return a * (kPiF / 180.0f);
        case MathOp::DEGREES:
            return a * (180.0f / kPiF);
    }
    return 0.0f;
}

float math_node(MathOp op, float a, float b, float c, bool use_clamp) {
    const float r = math_op(op, a, b, c);
    return use_clamp ? cclamp(r, 0.0f, 1.0f) : r;
}

// ---- Vector Math -----------------------------------------------------------------------------

bool parse_vector_math_op(std::string_view id, VectorMathOp* out) {
    using V = VectorMathOp;
    static constexpr std::array<std::pair<std::string_view, V>, 27> kTable{{
        {"ADD", V::ADD},
        {"SUBTRACT", V::SUBTRACT},
        {"MULTIPLY", V::MULTIPLY},
        {"DIVIDE", V::DIVIDE},
        {"MULTIPLY_ADD", V::MULTIPLY_ADD},
        {"CROSS_PRODUCT", V::CROSS_PRODUCT},
        {"PROJECT", V::PROJECT},
        {"REFLECT", V::REFLECT},
        {"REFRACT", V::REFRACT},
        {"FACEFORWARD", V::FACEFORWARD},
        {"DOT_PRODUCT", V::DOT_PRODUCT},
        {"DISTANCE", V::DISTANCE},
        {"LENGTH", V::LENGTH},
        {"SCALE", V::SCALE},
        {"NORMALIZE", V::NORMALIZE},
        {"ABSOLUTE", V::ABSOLUTE},
        {"MINIMUM", V::MINIMUM},
        {"MAXIMUM", V::MAXIMUM},
        {"FLOOR", V::FLOOR},
        {"CEIL", V::CEIL},
        {"FRACTION", V::FRACTION},
        {"MODULO", V::MODULO},
        {"WRAP", V::WRAP},
        {"SNAP", V::SNAP},
        {"SINE", V::SINE},
        {"COSINE", V::COSINE},
        {"TANGENT", V::TANGENT},
    }};
    return parse_enum(id, kTable, out);
}

bool vector_math_op_gives_value(VectorMathOp op) {
    return op == VectorMathOp::DOT_PRODUCT || op == VectorMathOp::DISTANCE ||
           op == VectorMathOp::LENGTH;
}

VectorMathResult vector_math_node(VectorMathOp op, float3 a, float3 b, float3 c, float scale) {
    using V = VectorMathOp;
    VectorMathResult r;
    switch (op) {
        case V::ADD:
            r.vector = a + b;
            break;
        case V::SUBTRACT:
            r.vector = a - b;
            break;
        case V::MULTIPLY:
            r.vector = a * b;
            break;
        case V::DIVIDE:
            r.vector = safe_divide(a, b);
            break;
        case V::MULTIPLY_ADD:
            r.vector = a * b + c;
            break;
        case V::CROSS_PRODUCT:
            r.vector = cross(a, b);
            break;
        case V::PROJECT:
            r.vector = project(a, b);
            break;
        case V::REFLECT:
            r.vector = reflect(a, b);
            break;
        case V::REFRACT:
            r.vector = refract(a, normalize_unsafe(b), scale);
            break;
        case V::FACEFORWARD:
            r.vector = dot(c, b) < 0.0f ? a : -a;
            break;
        case V::DOT_PRODUCT:
            r.value = dot(a, b);
            break;
        case V::DISTANCE:
            r.value = len(a - b);
            break;
        case V::LENGTH:
            r.value = len(a);
            break;
        case V::SCALE:
            r.vector = a * scale;
            break;
        case V::NORMALIZE:
            r.vector = safe_normalize(a);
            break;
        case V::ABSOLUTE:
            r.vector = map3(a, [](float x) { return std::fabs(x); });
            break;
        case V::MINIMUM:
            r.vector = {cmin(a.x, b.x), cmin(a.y, b.y), cmin(a.z, b.z)};
            break;
        case V::MAXIMUM:
            r.vector = {cmax(a.x, b.x), cmax(a.y, b.y), cmax(a.z, b.z)};
            break;
        case V::FLOOR:
            r.vector = floor3(a);
            break;
        case V::CEIL:
            r.vector = map3(a, [](float x) { return std::ceil(x); });
            break;
        case V::FRACTION:
            r.vector = a - floor3(a);
            break;
        case V::MODULO:
            r.vector = {safe_modulo(a.x, b.x), safe_modulo(a.y, b.y), safe_modulo(a.z, b.z)};
            break;
        case V::WRAP:
            r.vector = {wrap(a.x, b.x, c.x), wrap(a.y, b.y, c.y), wrap(a.z, b.z, c.z)};
            break;
        case V::SNAP:
            r.vector = floor3(safe_divide(a, b)) * b;
            break;
        case V::SINE:
            r.vector = map3(a, [](float x) { return std::sin(x); });
            break;
        case V::COSINE:
            r.vector = map3(a, [](float x) { return std::cos(x); });
            break;
        case V::TANGENT:
            r.vector = map3(a, [](float x) { return std::tan(x); });
            break;
    }
    return r;
}

// ---- Map Range, Clamp ------------------------------------------------------------------------

bool parse_map_range_interpolation(std::string_view id, MapRangeInterpolation* out) {
    using I = MapRangeInterpolation;
    static constexpr std::array<std::pair<std::string_view, I>, 4> kTable{{
        {"LINEAR", I::LINEAR},
        {"STEPPED", I::STEPPED},
        {"SMOOTHSTEP", I::SMOOTHSTEP},
        {"SMOOTHERSTEP", I::SMOOTHERSTEP},
    }};
    return parse_enum(id, kTable, out);
}

bool parse_map_range_data_type(std::string_view id, MapRangeDataType* out) {
    static constexpr std::array<std::pair<std::string_view, MapRangeDataType>, 2> kTable{{
        {"FLOAT", MapRangeDataType::FLOAT},
        {"FLOAT_VECTOR", MapRangeDataType::FLOAT_VECTOR},
    }};
    return parse_enum(id, kTable, out);
}

float map_range_node(MapRangeInterpolation type, float value, float from_min, float from_max,
                     float to_min, float to_max, float steps, bool clamp) {
    float result = 0.0f;
    if (from_max != from_min) {
        float factor = value;
        switch (type) {
            case MapRangeInterpolation::LINEAR:
                factor = (value - from_min) / (from_max - from_min);
                break;
            case MapRangeInterpolation::STEPPED:
                factor = (value - from_min) / (from_max - from_min);
                factor = steps > 0.0f ? std::floor(factor * (steps + 1.0f)) / steps : 0.0f;
                break;
            case MapRangeInterpolation::SMOOTHSTEP:
                factor = from_min > from_max ? 1.0f - smoothstep(from_max, from_min, factor)
                                             : smoothstep(from_min, from_max, factor);
                break;
            case MapRangeInterpolation::SMOOTHERSTEP:
                factor = from_min > from_max ? 1.0f - smootherstep(from_max, from_min, factor)
                                             : smootherstep(from_min, from_max, factor);
                break;
        }
        result = to_min + factor * (to_max - to_min);
    }
    return clamp ? clamp_node(ClampType::RANGE, result, to_min, to_max) : result;
}

float3 map_range_vector_node(MapRangeInterpolation type, float3 value, float3 from_min,
                             float3 from_max, float3 to_min, float3 to_max, float3 steps,
                             bool clamp) {
    float3 factor = safe_divide(value - from_min, from_max - from_min);
    switch (type) {
        case MapRangeInterpolation::LINEAR:
            break;
        case MapRangeInterpolation::STEPPED:
            for (int i = 0; i < 3; ++i) {
                factor[i] =
                    steps[i] > 0.0f ? std::floor(factor[i] * (steps[i] + 1.0f)) / steps[i] : 0.0f;
            }
            break;
        case MapRangeInterpolation::SMOOTHSTEP:
            for (int i = 0; i < 3; ++i) {
                const float t = cclamp(factor[i], 0.0f, 1.0f);
                factor[i] = (3.0f - 2.0f * t) * (t * t);
            }
            break;
        case MapRangeInterpolation::SMOOTHERSTEP:
            for (int i = 0; i < 3; ++i) {
                const float t = cclamp(factor[i], 0.0f, 1.0f);
                factor[i] = t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
            }
            break;
    }
    float3 result = to_min + factor * (to_max - to_min);
    const bool smooth =
        type == MapRangeInterpolation::SMOOTHSTEP || type == MapRangeInterpolation::SMOOTHERSTEP;
    if (clamp && !smooth) {
        for (int i = 0; i < 3; ++i) {
            result[i] = clamp_node(ClampType::RANGE, result[i], to_min[i], to_max[i]);
        }
    }
    return result;
}

bool parse_clamp_type(std::string_view id, ClampType* out) {
    static constexpr std::array<std::pair<std::string_view, ClampType>, 2> kTable{{
        {"MINMAX", ClampType::MINMAX},
        {"RANGE", ClampType::RANGE},
    }};
    return parse_enum(id, kTable, out);
}

float clamp_node(ClampType type, float value, float min, float max) {
    if (type == ClampType::RANGE && min > max) return cclamp(value, max, min);
    return cclamp(value, min, max);
}

// ---- Separate / Combine --------------------------------------------------------------------

bool parse_color_mode(std::string_view id, ColorMode* out) {
    static constexpr std::array<std::pair<std::string_view, ColorMode>, 3> kTable{{
        {"RGB", ColorMode::RGB},
        {"HSV", ColorMode::HSV},
        {"HSL", ColorMode::HSL},
    }};
    return parse_enum(id, kTable, out);
}

float3 separate_color_node(ColorMode mode, float3 color) {
    switch (mode) {
        case ColorMode::HSV:
            return rgb_to_hsv(color);
        case ColorMode::HSL:
            return rgb_to_hsl(color);
        case ColorMode::RGB:
            break;
    }
    return color;
}

float3 combine_color_node(ColorMode mode, float x, float y, float z) {
    const float3 v(x, y, z);
    switch (mode) {
        case ColorMode::HSV:
            return hsv_to_rgb(v);
        case ColorMode::HSL:
            return hsl_to_rgb(v);
        case ColorMode::RGB:
            break;
    }
    return v;
}

float3 separate_hsv_node(float3 color) { return rgb_to_hsv(color); }
float3 combine_hsv_node(float h, float s, float v) { return hsv_to_rgb({h, s, v}); }

float vector_to_float(float3 v) { return (v.x + v.y + v.z) * (1.0f / 3.0f); }

// ---- Blackbody ----------------------------------------------------------------------------

namespace {

// Cycles' fit (kernel/tables.h), one row per temperature band; the bands start at the
// temperatures of kBlackbodyBandStart.
constexpr float kBlackbodyBandStart[6] = {965.0f, 1167.0f, 1449.0f, 1902.0f, 3315.0f, 6365.0f};
constexpr float kBlackbodyR[7][3] = {
    {1.61919106e+03f, -2.05010916e-03f, 5.02995757e+00f},
    {2.48845471e+03f, -1.11330907e-03f, 3.22621544e+00f},
    {3.34143193e+03f, -4.86551192e-04f, 1.76486769e+00f},
    {4.09461742e+03f, -1.27446582e-04f, 7.25731635e-01f},
    {4.67028036e+03f, 2.91258199e-05f, 1.26703442e-01f},
    {4.59509185e+03f, 2.87495649e-05f, 1.50345020e-01f},
    {3.78717450e+03f, 9.35907826e-06f, 3.99075871e-01f},
};
constexpr float kBlackbodyG[7][3] = {
    {-4.88999748e+02f, 6.04330754e-04f, -7.55807526e-02f},
    {-7.55994277e+02f, 3.16730098e-04f, 4.78306139e-01f},
    {-1.02363977e+03f, 1.20223470e-04f, 9.36662319e-01f},
    {-1.26571316e+03f, 4.87340896e-06f, 1.27054498e+00f},
    {-1.42529332e+03f, -4.01150431e-05f, 1.43972784e+00f},
    {-1.17554822e+03f, -2.16378048e-05f, 1.30408023e+00f},
    {-5.00799571e+02f, -4.59832026e-06f, 1.09098763e+00f},
};
constexpr float kBlackbodyB[7][4] = {
    {5.96945309e-11f, -4.85742887e-08f, -9.70622247e-05f, -4.07936148e-03f},
    {2.40430366e-11f, 5.55021075e-08f, -1.98503712e-04f, 2.89312858e-02f},
    {-1.40949732e-11f, 1.89878968e-07f, -3.56632824e-04f, 9.10767778e-02f},
    {-3.61460868e-11f, 2.84822009e-07f, -4.93211319e-04f, 1.56723440e-01f},
    {-1.97075738e-11f, 1.75359352e-07f, -2.50542825e-04f, -2.22783266e-02f},
    {-1.61997957e-13f, -1.64216008e-08f, 3.86216271e-04f, -7.38077418e-01f},
    {6.72650283e-13f, -2.73078809e-08f, 4.24098264e-04f, -7.52335691e-01f},
};

}  // namespace

float3 blackbody_rec709(float kelvin) {
    if (kelvin >= 12000.0f) {
        return {0.8262954810464208f, 0.9945080501520986f, 1.566307710274283f};
    }
    if (kelvin < 800.0f) {  // a NaN passes both tests and gives NaN, as in Cycles
        return {5.413294490189271f, -0.20319390035873933f, -0.0822535242887164f};
    }
    int band = 0;
    while (band < 6 && kelvin >= kBlackbodyBandStart[band]) ++band;
    const float* r = kBlackbodyR[band];
    const float* g = kBlackbodyG[band];
    const float* b = kBlackbodyB[band];
    const float inv = 1.0f / kelvin;
    return {r[0] * inv + r[1] * kelvin + r[2], g[0] * inv + g[1] * kelvin + g[2],
            ((b[0] * kelvin + b[1]) * kelvin + b[2]) * kelvin + b[3]};
}

float3 blackbody_node(float kelvin) {
    const float3 c = blackbody_rec709(kelvin);
    return {cmax(c.x, 0.0f), cmax(c.y, 0.0f), cmax(c.z, 0.0f)};
}

// ---- Wavelength ----------------------------------------------------------------------------

namespace {

// CIE 1931 2-degree colour matching functions x, y, z from 380 nm to 780 nm by 5 nm, as in
// Cycles' kernel/tables.h.
constexpr float kCieXyz[81][3] = {
    {0.0014f, 0.0000f, 0.0065f}, {0.0022f, 0.0001f, 0.0105f}, {0.0042f, 0.0001f, 0.0201f},
    {0.0076f, 0.0002f, 0.0362f}, {0.0143f, 0.0004f, 0.0679f}, {0.0232f, 0.0006f, 0.1102f},
    {0.0435f, 0.0012f, 0.2074f}, {0.0776f, 0.0022f, 0.3713f}, {0.1344f, 0.0040f, 0.6456f},
    {0.2148f, 0.0073f, 1.0391f}, {0.2839f, 0.0116f, 1.3856f}, {0.3285f, 0.0168f, 1.6230f},
    {0.3483f, 0.0230f, 1.7471f}, {0.3481f, 0.0298f, 1.7826f}, {0.3362f, 0.0380f, 1.7721f},
    {0.3187f, 0.0480f, 1.7441f}, {0.2908f, 0.0600f, 1.6692f}, {0.2511f, 0.0739f, 1.5281f},
    {0.1954f, 0.0910f, 1.2876f}, {0.1421f, 0.1126f, 1.0419f}, {0.0956f, 0.1390f, 0.8130f},
    {0.0580f, 0.1693f, 0.6162f}, {0.0320f, 0.2080f, 0.4652f}, {0.0147f, 0.2586f, 0.3533f},
    {0.0049f, 0.3230f, 0.2720f}, {0.0024f, 0.4073f, 0.2123f}, {0.0093f, 0.5030f, 0.1582f},
    {0.0291f, 0.6082f, 0.1117f}, {0.0633f, 0.7100f, 0.0782f}, {0.1096f, 0.7932f, 0.0573f},
    {0.1655f, 0.8620f, 0.0422f}, {0.2257f, 0.9149f, 0.0298f}, {0.2904f, 0.9540f, 0.0203f},
    {0.3597f, 0.9803f, 0.0134f}, {0.4334f, 0.9950f, 0.0087f}, {0.5121f, 1.0000f, 0.0057f},
    {0.5945f, 0.9950f, 0.0039f}, {0.6784f, 0.9786f, 0.0027f}, {0.7621f, 0.9520f, 0.0021f},
    {0.8425f, 0.9154f, 0.0018f}, {0.9163f, 0.8700f, 0.0017f}, {0.9786f, 0.8163f, 0.0014f},
    {1.0263f, 0.7570f, 0.0011f}, {1.0567f, 0.6949f, 0.0010f}, {1.0622f, 0.6310f, 0.0008f},
    {1.0456f, 0.5668f, 0.0006f}, {1.0026f, 0.5030f, 0.0003f}, {0.9384f, 0.4412f, 0.0002f},
    {0.8544f, 0.3810f, 0.0002f}, {0.7514f, 0.3210f, 0.0001f}, {0.6424f, 0.2650f, 0.0000f},
    {0.5419f, 0.2170f, 0.0000f}, {0.4479f, 0.1750f, 0.0000f}, {0.3608f, 0.1382f, 0.0000f},
    {0.2835f, 0.1070f, 0.0000f}, {0.2187f, 0.0816f, 0.0000f}, {0.1649f, 0.0610f, 0.0000f},
    {0.1212f, 0.0446f, 0.0000f}, {0.0874f, 0.0320f, 0.0000f}, {0.0636f, 0.0232f, 0.0000f},
    {0.0468f, 0.0170f, 0.0000f}, {0.0329f, 0.0119f, 0.0000f}, {0.0227f, 0.0082f, 0.0000f},
    {0.0158f, 0.0057f, 0.0000f}, {0.0114f, 0.0041f, 0.0000f}, {0.0081f, 0.0029f, 0.0000f},
    {0.0058f, 0.0021f, 0.0000f}, {0.0041f, 0.0015f, 0.0000f}, {0.0029f, 0.0010f, 0.0000f},
    {0.0020f, 0.0007f, 0.0000f}, {0.0014f, 0.0005f, 0.0000f}, {0.0010f, 0.0004f, 0.0000f},
    {0.0007f, 0.0002f, 0.0000f}, {0.0005f, 0.0002f, 0.0000f}, {0.0003f, 0.0001f, 0.0000f},
    {0.0002f, 0.0001f, 0.0000f}, {0.0002f, 0.0001f, 0.0000f}, {0.0001f, 0.0000f, 0.0000f},
    {0.0001f, 0.0000f, 0.0000f}, {0.0001f, 0.0000f, 0.0000f}, {0.0000f, 0.0000f, 0.0000f},
};

}  // namespace

float3 wavelength_to_xyz(float lambda_nm) {
    float pos = (lambda_nm - 380.0f) * (1.0f / 5.0f);
    // Cycles truncates pos toward zero and keeps intervals 0..79: pos in (-1, 80).
    if (!(pos > -1.0f && pos < 80.0f)) return float3(0.0f);
    const int i = static_cast<int>(pos);
    pos -= static_cast<float>(i);
    const float3 lo(kCieXyz[i][0], kCieXyz[i][1], kCieXyz[i][2]);
    const float3 hi(kCieXyz[i + 1][0], kCieXyz[i + 1][1], kCieXyz[i + 1][2]);
    return lo + pos * (hi - lo);
}

float3 wavelength_node(float lambda_nm, const ColorMatrix& xyz_to_rgb) {
    const float3 xyz = wavelength_to_xyz(lambda_nm);
    float3 rgb(dot(xyz_to_rgb.r, xyz), dot(xyz_to_rgb.g, xyz), dot(xyz_to_rgb.b, xyz));
    rgb *= 1.0f / 2.52f;
    return {cmax(rgb.x, 0.0f), cmax(rgb.y, 0.0f), cmax(rgb.z, 0.0f)};
}

}  // namespace glint::render::shader
