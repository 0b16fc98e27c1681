// Cycles 3.4's color node arithmetic (kernel/svm/color_util.h, mix.h, hsv.h, brightness.h,
// gamma.h, invert.h, ramp.h; util/color.h), restated in single precision.
#include "render/shader/color_nodes.h"

#include "render/shader/enum_table.h"

#include <array>
#include <cmath>
#include <utility>

namespace glint::render::shader {
namespace {

// Cycles' own min/max (a comparison, not fminf/fmaxf): they decide which side a NaN lands on.
float cmin(float a, float b) { return a < b ? a : b; }
float cmax(float a, float b) { return a > b ? a : b; }
float saturate(float a) { return cmin(cmax(a, 0.0f), 1.0f); }
float3 saturate(float3 a) { return {saturate(a.x), saturate(a.y), saturate(a.z)}; }
float3 lerp(float3 a, float3 b, float t) { return a + t * (b - a); }

// Applies a per-channel rule to each component of a pair of colors.
template <typename F>
float3 per_channel(float3 a, float3 b, F&& rule) {
    return {rule(a.x, b.x), rule(a.y, b.y), rule(a.z, b.z)};
}

float3 blend_screen(float t, float3 a, float3 b) {
    const float3 one(1.0f);
    return one - (float3(1.0f - t) + t * (one - b)) * (one - a);
}

float3 blend_overlay(float t, float3 a, float3 b) {
    const float tm = 1.0f - t;
    return per_channel(a, b, [&](float x, float y) {
        return x < 0.5f ? x * (tm + 2.0f * t * y)
                        : 1.0f - (tm + 2.0f * t * (1.0f - y)) * (1.0f - x);
    });
}

float3 blend_divide(float t, float3 a, float3 b) {
    const float tm = 1.0f - t;
    return per_channel(a, b, [&](float x, float y) { return y != 0.0f ? tm * x + t * x / y : x; });
}

float3 blend_dodge(float t, float3 a, float3 b) {
    return per_channel(a, b, [&](float x, float y) {
        if (x == 0.0f) return x;
        const float d = 1.0f - t * y;
        if (d <= 0.0f) return 1.0f;
        const float q = x / d;
        return q > 1.0f ? 1.0f : q;
    });
}

float3 blend_burn(float t, float3 a, float3 b) {
    const float tm = 1.0f - t;
    return per_channel(a, b, [&](float x, float y) {
        const float d = tm + t * y;
        if (d <= 0.0f) return 0.0f;
        const float q = 1.0f - (1.0f - x) / d;
        if (q < 0.0f) return 0.0f;
        return q > 1.0f ? 1.0f : q;
    });
}

// HUE and COLOR: take b's hue (and for COLOR its saturation) when b is not gray.
float3 blend_hue_color(float t, float3 a, float3 b, bool take_saturation) {
    const float3 hsv_b = rgb_to_hsv(b);
    if (hsv_b.y == 0.0f) return a;
    float3 hsv = rgb_to_hsv(a);
    hsv.x = hsv_b.x;
    if (take_saturation) hsv.y = hsv_b.y;
    return lerp(a, hsv_to_rgb(hsv), t);
}

float3 blend_saturation(float t, float3 a, float3 b) {
    float3 hsv = rgb_to_hsv(a);
    if (hsv.y == 0.0f) return a;
    const float3 hsv_b = rgb_to_hsv(b);
    hsv.y = (1.0f - t) * hsv.y + t * hsv_b.y;
    return hsv_to_rgb(hsv);
}

float3 blend_value(float t, float3 a, float3 b) {
    float3 hsv = rgb_to_hsv(a);
    const float3 hsv_b = rgb_to_hsv(b);
    hsv.z = (1.0f - t) * hsv.z + t * hsv_b.z;
    return hsv_to_rgb(hsv);
}

float3 blend_soft_light(float t, float3 a, float3 b) {
    const float3 one(1.0f);
    const float3 screen = one - (one - b) * (one - a);
    return (1.0f - t) * a + t * ((one - a) * b * a + a * screen);
}


}  // namespace

// ---- Mix -----------------------------------------------------------------------------------

bool parse_mix_blend(std::string_view id, MixBlend* out) {
    using B = MixBlend;
    static constexpr std::array<std::pair<std::string_view, B>, 18> kTable{{
        {"MIX", B::MIX},
        {"DARKEN", B::DARKEN},
        {"MULTIPLY", B::MULTIPLY},
        {"BURN", B::BURN},
        {"LIGHTEN", B::LIGHTEN},
        {"SCREEN", B::SCREEN},
        {"DODGE", B::DODGE},
        {"ADD", B::ADD},
        {"OVERLAY", B::OVERLAY},
        {"SOFT_LIGHT", B::SOFT_LIGHT},
        {"LINEAR_LIGHT", B::LINEAR_LIGHT},
        {"DIFFERENCE", B::DIFFERENCE},
        {"SUBTRACT", B::SUBTRACT},
        {"DIVIDE", B::DIVIDE},
        {"HUE", B::HUE},
        {"SATURATION", B::SATURATION},
        {"COLOR", B::COLOR},
        {"VALUE", B::VALUE},
    }};
    return parse_enum(id, kTable, out);
}

bool parse_mix_data_type(std::string_view id, MixDataType* out) {
    static constexpr std::array<std::pair<std::string_view, MixDataType>, 3> kTable{{
        {"FLOAT", MixDataType::FLOAT},
        {"VECTOR", MixDataType::VECTOR},
        {"RGBA", MixDataType::RGBA},
    }};
    return parse_enum(id, kTable, out);
}

bool parse_mix_factor_mode(std::string_view id, MixFactorMode* out) {
    static constexpr std::array<std::pair<std::string_view, MixFactorMode>, 2> kTable{{
        {"UNIFORM", MixFactorMode::UNIFORM},
        {"NON_UNIFORM", MixFactorMode::NON_UNIFORM},
    }};
    return parse_enum(id, kTable, out);
}

float3 mix_blend(MixBlend blend, float t, float3 a, float3 b) {
    switch (blend) {
        case MixBlend::MIX:
            return lerp(a, b, t);
        case MixBlend::ADD:
            return lerp(a, a + b, t);
        case MixBlend::MULTIPLY:
            return lerp(a, a * b, t);
        case MixBlend::SUBTRACT:
            return lerp(a, a - b, t);
        case MixBlend::SCREEN:
            return blend_screen(t, a, b);
        case MixBlend::OVERLAY:
            return blend_overlay(t, a, b);
        case MixBlend::DIVIDE:
            return blend_divide(t, a, b);
        case MixBlend::DIFFERENCE:
            return lerp(a, per_channel(a, b, [](float x, float y) { return std::fabs(x - y); }), t);
        case MixBlend::DARKEN:
            return lerp(a, per_channel(a, b, cmin), t);
        case MixBlend::LIGHTEN:
            return lerp(a, per_channel(a, b, cmax), t);
        case MixBlend::DODGE:
            return blend_dodge(t, a, b);
        case MixBlend::BURN:
            return blend_burn(t, a, b);
        case MixBlend::HUE:
            return blend_hue_color(t, a, b, false);
        case MixBlend::SATURATION:
            return blend_saturation(t, a, b);
        case MixBlend::VALUE:
            return blend_value(t, a, b);
        case MixBlend::COLOR:
            return blend_hue_color(t, a, b, true);
        case MixBlend::SOFT_LIGHT:
            return blend_soft_light(t, a, b);
        case MixBlend::LINEAR_LIGHT:
            return a + t * (2.0f * b + float3(-1.0f));
    }
    return float3(0.0f);
}

float3 mix_rgb_node(MixBlend blend, float fac, float3 color1, float3 color2, bool use_clamp) {
    const float3 r = mix_blend(blend, saturate(fac), color1, color2);
    return use_clamp ? saturate(r) : r;
}

float3 mix_color_node(MixBlend blend, float fac, float3 a, float3 b, bool clamp_factor,
                      bool clamp_result) {
    const float3 r = mix_blend(blend, clamp_factor ? saturate(fac) : fac, a, b);
    return clamp_result ? saturate(r) : r;
}

float mix_float_node(float fac, float a, float b, bool clamp_factor) {
    const float t = clamp_factor ? saturate(fac) : fac;
    return a * (1.0f - t) + b * t;
}

float3 mix_vector_node(float fac, float3 a, float3 b, bool clamp_factor) {
    const float t = clamp_factor ? saturate(fac) : fac;
    return a * (float3(1.0f) - float3(t)) + b * t;
}

float3 mix_vector_non_uniform_node(float3 fac, float3 a, float3 b, bool clamp_factor) {
    const float3 t = clamp_factor ? saturate(fac) : fac;
    return a * (float3(1.0f) - t) + b * t;
}

// ---- Color spaces --------------------------------------------------------------------------

float3 rgb_to_hsv(float3 rgb) {
    const float hi = std::fmax(rgb.x, std::fmax(rgb.y, rgb.z));
    const float lo = cmin(rgb.x, cmin(rgb.y, rgb.z));
    const float delta = hi - lo;
    const float s = hi != 0.0f ? delta / hi : 0.0f;
    float h = 0.0f;
    if (s != 0.0f) {
        const float3 c = (float3(hi) - rgb) / float3(delta);
        if (rgb.x == hi) {
            h = c.z - c.y;
        } else if (rgb.y == hi) {
            h = 2.0f + c.x - c.z;
        } else {
            h = 4.0f + c.y - c.x;
        }
        h /= 6.0f;
        if (h < 0.0f) h += 1.0f;
    }
    return {h, s, hi};
}

float3 hsv_to_rgb(float3 hsv) {
    float h = hsv.x;
    const float s = hsv.y, v = hsv.z;
    if (s == 0.0f) return float3(v);
    if (h == 1.0f) h = 0.0f;
    h *= 6.0f;
    const float sector = std::floor(h);
    const float f = h - sector;
    const float p = v * (1.0f - s);
    const float q = v * (1.0f - s * f);
    const float t = v * (1.0f - s * (1.0f - f));
    if (sector == 0.0f) return {v, t, p};
    if (sector == 1.0f) return {q, v, p};
    if (sector == 2.0f) return {p, v, t};
    if (sector == 3.0f) return {p, q, v};
    if (sector == 4.0f) return {t, p, v};
    return {v, p, q};  // sector 5, and any hue outside [0, 1]
}

float3 rgb_to_hsl(float3 rgb) {
    const float hi = std::fmax(rgb.x, std::fmax(rgb.y, rgb.z));
    const float lo = cmin(rgb.x, cmin(rgb.y, rgb.z));
    const float l = cmin(1.0f, (hi + lo) / 2.0f);
    float h = 0.0f, s = 0.0f;
    if (hi != lo) {
        const float delta = hi - lo;
        s = l > 0.5f ? delta / (2.0f - hi - lo) : delta / (hi + lo);
        if (hi == rgb.x) {
            h = (rgb.y - rgb.z) / delta + (rgb.y < rgb.z ? 6.0f : 0.0f);
        } else if (hi == rgb.y) {
            h = (rgb.z - rgb.x) / delta + 2.0f;
        } else {
            h = (rgb.x - rgb.y) / delta + 4.0f;
        }
    }
    h /= 6.0f;
    return {h, s, l};
}

float3 hsl_to_rgb(float3 hsl) {
    const float h = hsl.x, s = hsl.y, l = hsl.z;
    const float r = saturate(std::fabs(h * 6.0f - 3.0f) - 1.0f);
    const float g = saturate(2.0f - std::fabs(h * 6.0f - 2.0f));
    const float b = saturate(2.0f - std::fabs(h * 6.0f - 4.0f));
    const float chroma = (1.0f - std::fabs(2.0f * l - 1.0f)) * s;
    return {(r - 0.5f) * chroma + l, (g - 0.5f) * chroma + l, (b - 0.5f) * chroma + l};
}

// ---- Color adjustment nodes ------------------------------------------------------------------

float3 hue_saturation_value_node(float hue, float saturation, float value, float fac,
                                 float3 color) {
    float3 hsv = rgb_to_hsv(color);
    // fmodf keeps the sign: a hue shifted below 0 stays negative, as in Cycles.
    hsv.x = std::fmod(hsv.x + hue + 0.5f, 1.0f);
    hsv.y = saturate(hsv.y * saturation);
    hsv.z *= value;
    const float3 shifted = hsv_to_rgb(hsv);
    const float3 mixed =
        per_channel(shifted, color, [&](float x, float y) { return fac * x + (1.0f - fac) * y; });
    return per_channel(mixed, mixed, [](float x, float) { return cmax(x, 0.0f); });
}

float3 bright_contrast_node(float3 color, float bright, float contrast) {
    const float a = 1.0f + contrast;
    const float b = bright - contrast * 0.5f;
    return per_channel(color, color, [&](float x, float) { return cmax(a * x + b, 0.0f); });
}

float3 gamma_node(float3 color, float gamma) {
    if (gamma == 0.0f) return float3(1.0f);
    return per_channel(color, color,
                       [&](float x, float) { return x > 0.0f ? std::pow(x, gamma) : x; });
}

float3 invert_node(float fac, float3 color) {
    return per_channel(color, color,
                       [&](float x, float) { return fac * (1.0f - x) + (1.0f - fac) * x; });
}

float rgb_to_bw_node(float3 color, float3 rgb_to_y) { return dot(color, rgb_to_y); }

// ---- Ramps and curves --------------------------------------------------------------------------

namespace {

float4 operator-(float4 a, float4 b) { return {a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w}; }
float4 operator+(float4 a, float4 b) { return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w}; }
float4 operator*(float4 a, float s) { return {a.x * s, a.y * s, a.z * s, a.w * s}; }
float4 operator*(float s, float4 a) { return a * s; }

// The lookup shared by float and float4 tables.
template <typename T>
T ramp_lookup(std::span<const T> table, float f, bool interpolate, bool extrapolate) {
    const int n = static_cast<int>(table.size());
    if (extrapolate && (f < 0.0f || f > 1.0f)) {
        // Continue the slope of the first or last pair of entries.
        const bool low = f < 0.0f;
        const T end = low ? table[0] : table[n - 1];
        const T slope = end - (low ? table[1] : table[n - 2]);
        const float beyond = low ? -f : f - 1.0f;
        return end + slope * beyond * static_cast<float>(n - 1);
    }
    const float pos = saturate(f) * static_cast<float>(n - 1);  // NaN -> 0
    int i = static_cast<int>(pos);
    i = i < 0 ? 0 : (i > n - 1 ? n - 1 : i);
    const float t = pos - static_cast<float>(i);
    T v = table[i];
    if (interpolate && t > 0.0f) v = (1.0f - t) * v + t * table[i + 1];
    return v;
}

std::vector<float4> bake_xyz(const std::function<float3(float)>& eval, float min_x, float max_x,
                             int size) {
    std::vector<float4> table(static_cast<std::size_t>(size));
    const float range = max_x - min_x;
    for (int i = 0; i < size; ++i) {
        const float x = min_x + static_cast<float>(i) / static_cast<float>(size - 1) * range;
        const float3 v = eval(x);
        table[static_cast<std::size_t>(i)] = {v.x, v.y, v.z, 1.0f};
    }
    return table;
}

}  // namespace

float4 rgb_ramp_lookup(std::span<const float4> table, float f, bool interpolate, bool extrapolate) {
    return ramp_lookup(table, f, interpolate, extrapolate);
}

float float_ramp_lookup(std::span<const float> table, float f, bool interpolate, bool extrapolate) {
    return ramp_lookup(table, f, interpolate, extrapolate);
}

bool parse_color_ramp_interpolation(std::string_view id, ColorRampInterpolation* out) {
    using I = ColorRampInterpolation;
    static constexpr std::array<std::pair<std::string_view, I>, 5> kTable{{
        {"EASE", I::EASE},
        {"CARDINAL", I::CARDINAL},
        {"LINEAR", I::LINEAR},
        {"B_SPLINE", I::B_SPLINE},
        {"CONSTANT", I::CONSTANT},
    }};
    return parse_enum(id, kTable, out);
}

bool color_ramp_interpolates(ColorRampInterpolation interpolation) {
    return interpolation != ColorRampInterpolation::CONSTANT;
}

float4 color_ramp_node(std::span<const float4> table, float fac, bool interpolate) {
    return rgb_ramp_lookup(table, fac, interpolate, false);
}

bool parse_curve_extend(std::string_view id, CurveExtend* out) {
    static constexpr std::array<std::pair<std::string_view, CurveExtend>, 2> kTable{{
        {"HORIZONTAL", CurveExtend::HORIZONTAL},
        {"EXTRAPOLATED", CurveExtend::EXTRAPOLATED},
    }};
    return parse_enum(id, kTable, out);
}

float3 rgb_curves_node(std::span<const float4> table, float min_x, float max_x, bool extrapolate,
                       float fac, float3 color) {
    const float range = max_x - min_x;
    const float3 pos = (color - float3(min_x)) / range;
    const float3 curve{rgb_ramp_lookup(table, pos.x, true, extrapolate).x,
                       rgb_ramp_lookup(table, pos.y, true, extrapolate).y,
                       rgb_ramp_lookup(table, pos.z, true, extrapolate).z};
    return (1.0f - fac) * color + fac * curve;
}

float3 vector_curves_node(std::span<const float4> table, float min_x, float max_x, bool extrapolate,
                          float fac, float3 vector) {
    // Cycles runs Vector Curves through the same SVM node as RGB Curves.
    return rgb_curves_node(table, min_x, max_x, extrapolate, fac, vector);
}

float float_curve_node(std::span<const float> table, float min_x, float max_x, bool extrapolate,
                       float fac, float value) {
    const float range = max_x - min_x;
    const float pos = (value - min_x) / range;
    const float v = float_ramp_lookup(table, pos, true, extrapolate);
    return (1.0f - fac) * value + fac * v;
}

std::vector<float4> bake_color_ramp(const std::function<float4(float)>& ramp, int size) {
    std::vector<float4> table(static_cast<std::size_t>(size));
    for (int i = 0; i < size; ++i) {
        table[static_cast<std::size_t>(i)] =
            ramp(static_cast<float>(i) / static_cast<float>(size - 1));
    }
    return table;
}

std::vector<float4> bake_rgb_curves(const std::function<float(int curve, float x)>& curve,
                                    float min_x, float max_x, int size) {
    return bake_xyz(
        [&](float x) {
            const float c = curve(3, x);
            return float3(curve(0, c), curve(1, c), curve(2, c));
        },
        min_x, max_x, size);
}

std::vector<float4> bake_vector_curves(const std::function<float(int curve, float x)>& curve,
                                       float min_x, float max_x, int size) {
    return bake_xyz([&](float x) { return float3(curve(0, x), curve(1, x), curve(2, x)); }, min_x,
                    max_x, size);
}

std::vector<float> bake_float_curve(const std::function<float(float x)>& curve, float min_x,
                                    float max_x, int size) {
    std::vector<float> table(static_cast<std::size_t>(size));
    const float range = max_x - min_x;
    for (int i = 0; i < size; ++i) {
        table[static_cast<std::size_t>(i)] =
            curve(min_x + static_cast<float>(i) / static_cast<float>(size - 1) * range);
    }
    return table;
}

}  // namespace glint::render::shader
