// Texture nodes: procedural ones (tex_noise.h, tex_voronoi.h, tex_procedural.h) and images
// (Image and Environment Texture) read through the render's TextureCache. An unlinked Vector
// input means the node's default coordinates, as in Cycles: Generated for procedural
// textures, the active UV map for images, the direction for environments.
#include <algorithm>
#include <cmath>

#include "render/shader/compiler.h"
#include "render/shader/sky_nodes.h"
#include "render/shader/tex_noise.h"
#include "render/shader/tex_procedural.h"
#include "render/shader/tex_voronoi.h"
#include "render/textures/image_texture.h"

namespace glint::render::shader {

namespace {

using R = float3*;
using G = const ShaderGlobals&;

int tex_vector(Compiler& c, int n, int fallback) {
    return c.linked(n, "Vector") ? c.in(n, "Vector", 'v') : fallback;
}

NoiseDimensions dimensions(Compiler& c, int n, const char* key) {
    const std::string d = c.enum_prop(n, key, "3D");
    if (d == "1D") return NoiseDimensions::D1;
    if (d == "2D") return NoiseDimensions::D2;
    if (d == "4D") return NoiseDimensions::D4;
    if (d != "3D") c.unsupported(n, std::string(key) + " '" + d + "': using 3D");
    return NoiseDimensions::D3;
}

void noise(Compiler& c, int n) {
    const int fac = c.fresh(), color = c.fresh();
    Op op;
    op.fn = [](const Op& o, R r, G) {
        NoiseTextureInputs in;
        in.vector = r[o.in[0]];
        in.w = r[o.in[1]].x;
        in.scale = r[o.in[2]].x;
        in.detail = r[o.in[3]].x;
        in.roughness = r[o.in[4]].x;
        in.distortion = r[o.in[5]].x;
        NoiseTextureParams p;
        p.dimensions = static_cast<NoiseDimensions>(o.i[0]);
        const NoiseTextureOutput out = noise_texture(in, p, true);
        r[o.out[0]] = float3(out.fac, 0, 0);
        r[o.out[1]] = out.color;
    };
    const int ins[6] = {tex_vector(c, n, kRegGenerated), c.in(n, "W", 'f'),
                        c.in(n, "Scale", 'f', float3(5)), c.in(n, "Detail", 'f', float3(2)),
                        c.in(n, "Roughness", 'f', float3(0.5f)), c.in(n, "Distortion", 'f')};
    std::copy(ins, ins + 6, op.in);
    op.out[0] = fac;
    op.out[1] = color;
    op.i[0] = static_cast<int>(dimensions(c, n, "noise_dimensions"));
    c.emit(op);
    c.set_out(n, "Fac", fac);
    c.set_out(n, "Color", color);
}

void white_noise(Compiler& c, int n) {
    const int value = c.fresh(), color = c.fresh();
    Op op;
    op.fn = [](const Op& o, R r, G) {
        WhiteNoiseInputs in;
        in.vector = r[o.in[0]];
        in.w = r[o.in[1]].x;
        WhiteNoiseParams p;
        p.dimensions = static_cast<NoiseDimensions>(o.i[0]);
        const WhiteNoiseOutput out = white_noise_texture(in, p);
        r[o.out[0]] = float3(out.value, 0, 0);
        r[o.out[1]] = out.color;
    };
    // White Noise reads its Vector as given: unlinked, it is (0, 0, 0) as in Cycles.
    op.in[0] = c.in(n, "Vector", 'v');
    op.in[1] = c.in(n, "W", 'f');
    op.out[0] = value;
    op.out[1] = color;
    op.i[0] = static_cast<int>(dimensions(c, n, "noise_dimensions"));
    c.emit(op);
    c.set_out(n, "Value", value);
    c.set_out(n, "Color", color);
}

void musgrave(Compiler& c, int n) {
    const std::string type = c.enum_prop(n, "musgrave_type", "FBM");
    MusgraveType t = MusgraveType::FBM;
    if (type == "MULTIFRACTAL") t = MusgraveType::MULTIFRACTAL;
    else if (type == "RIDGED_MULTIFRACTAL") t = MusgraveType::RIDGED_MULTIFRACTAL;
    else if (type == "HYBRID_MULTIFRACTAL") t = MusgraveType::HYBRID_MULTIFRACTAL;
    else if (type == "HETERO_TERRAIN") t = MusgraveType::HETERO_TERRAIN;
    const int fac = c.fresh();
    Op op;
    op.fn = [](const Op& o, R r, G) {
        MusgraveTextureInputs in;
        in.vector = r[o.in[0]];
        in.w = r[o.in[1]].x;
        in.scale = r[o.in[2]].x;
        in.detail = r[o.in[3]].x;
        in.dimension = r[o.in[4]].x;
        in.lacunarity = r[o.in[5]].x;
        in.offset = r[o.in[6]].x;
        in.gain = r[o.in[7]].x;
        MusgraveTextureParams p;
        p.type = static_cast<MusgraveType>(o.i[0]);
        p.dimensions = static_cast<NoiseDimensions>(o.i[1]);
        r[o.out[0]] = float3(musgrave_texture(in, p).fac, 0, 0);
    };
    const int ins[8] = {tex_vector(c, n, kRegGenerated), c.in(n, "W", 'f'),
                        c.in(n, "Scale", 'f', float3(5)), c.in(n, "Detail", 'f', float3(2)),
                        c.in(n, "Dimension", 'f', float3(2)), c.in(n, "Lacunarity", 'f', float3(2)),
                        c.in(n, "Offset", 'f'), c.in(n, "Gain", 'f', float3(1))};
    std::copy(ins, ins + 8, op.in);
    op.out[0] = fac;
    op.i[0] = static_cast<int>(t);
    op.i[1] = static_cast<int>(dimensions(c, n, "musgrave_dimensions"));
    c.emit(op);
    c.set_out(n, "Fac", fac);
}

void voronoi(Compiler& c, int n) {
    VoronoiTextureParams p;
    p.dimensions = dimensions(c, n, "voronoi_dimensions");
    const std::string f = c.enum_prop(n, "feature", "F1");
    p.feature = f == "F2" ? VoronoiFeature::F2 : f == "SMOOTH_F1" ? VoronoiFeature::SMOOTH_F1
              : f == "DISTANCE_TO_EDGE" ? VoronoiFeature::DISTANCE_TO_EDGE
              : f == "N_SPHERE_RADIUS" ? VoronoiFeature::N_SPHERE_RADIUS : VoronoiFeature::F1;
    const std::string m = c.enum_prop(n, "distance", "EUCLIDEAN");
    p.metric = m == "MANHATTAN" ? VoronoiMetric::MANHATTAN : m == "CHEBYCHEV"
             ? VoronoiMetric::CHEBYCHEV : m == "MINKOWSKI" ? VoronoiMetric::MINKOWSKI
             : VoronoiMetric::EUCLIDEAN;
    const int dist = c.fresh(), color = c.fresh(), pos = c.fresh(), w = c.fresh(),
              radius = c.fresh();
    Op op;
    op.fn = [](const Op& o, R r, G) {
        VoronoiTextureInputs in;
        in.vector = r[o.in[0]];
        in.w = r[o.in[1]].x;
        in.scale = r[o.in[2]].x;
        in.smoothness = r[o.in[3]].x;
        in.exponent = r[o.in[4]].x;
        in.randomness = r[o.in[5]].x;
        VoronoiTextureParams p;
        p.dimensions = static_cast<NoiseDimensions>(o.i[0]);
        p.feature = static_cast<VoronoiFeature>(o.i[1]);
        p.metric = static_cast<VoronoiMetric>(o.i[2]);
        const VoronoiTextureOutput out = voronoi_texture(in, p);
        r[o.out[0]] = float3(out.distance, 0, 0);
        r[o.out[1]] = out.color;
        r[o.out[2]] = out.position;
        r[o.out[3]] = float3(out.w, 0, 0);
        r[o.out[4]] = float3(out.radius, 0, 0);
    };
    const int ins[6] = {tex_vector(c, n, kRegGenerated), c.in(n, "W", 'f'),
                        c.in(n, "Scale", 'f', float3(5)), c.in(n, "Smoothness", 'f', float3(1)),
                        c.in(n, "Exponent", 'f', float3(0.5f)),
                        c.in(n, "Randomness", 'f', float3(1))};
    std::copy(ins, ins + 6, op.in);
    const int outs[5] = {dist, color, pos, w, radius};
    std::copy(outs, outs + 5, op.out);
    op.i[0] = static_cast<int>(p.dimensions);
    op.i[1] = static_cast<int>(p.feature);
    op.i[2] = static_cast<int>(p.metric);
    c.emit(op);
    c.set_out(n, "Distance", dist);
    c.set_out(n, "Color", color);
    c.set_out(n, "Position", pos);
    c.set_out(n, "W", w);
    c.set_out(n, "Radius", radius);
}

void wave(Compiler& c, int n) {
    WaveTextureParams p;
    p.type = c.enum_prop(n, "wave_type", "BANDS") == "RINGS" ? WaveType::RINGS : WaveType::BANDS;
    const std::string bd = c.enum_prop(n, "bands_direction", "X");
    p.bands_direction = bd == "Y" ? WaveBandsDirection::Y : bd == "Z" ? WaveBandsDirection::Z
                      : bd == "DIAGONAL" ? WaveBandsDirection::DIAGONAL : WaveBandsDirection::X;
    const std::string rd = c.enum_prop(n, "rings_direction", "X");
    p.rings_direction = rd == "Y" ? WaveRingsDirection::Y : rd == "Z" ? WaveRingsDirection::Z
                      : rd == "SPHERICAL" ? WaveRingsDirection::SPHERICAL : WaveRingsDirection::X;
    const std::string pr = c.enum_prop(n, "wave_profile", "SIN");
    p.profile = pr == "SAW" ? WaveProfile::SAW : pr == "TRI" ? WaveProfile::TRI : WaveProfile::SIN;
    const int color = c.fresh(), fac = c.fresh();
    Op op;
    op.fn = [](const Op& o, R r, G) {
        WaveTextureInputs in;
        in.vector = r[o.in[0]];
        in.scale = r[o.in[1]].x;
        in.distortion = r[o.in[2]].x;
        in.detail = r[o.in[3]].x;
        in.detail_scale = r[o.in[4]].x;
        in.detail_roughness = r[o.in[5]].x;
        in.phase_offset = r[o.in[6]].x;
        WaveTextureParams p;
        p.type = static_cast<WaveType>(o.i[0]);
        p.bands_direction = static_cast<WaveBandsDirection>(o.i[1]);
        p.rings_direction = static_cast<WaveRingsDirection>(o.i[2]);
        p.profile = static_cast<WaveProfile>(o.i[3]);
        const WaveTextureOutput out = wave_texture(in, p);
        r[o.out[0]] = out.color;
        r[o.out[1]] = float3(out.fac, 0, 0);
    };
    const int ins[7] = {tex_vector(c, n, kRegGenerated), c.in(n, "Scale", 'f', float3(5)),
                        c.in(n, "Distortion", 'f'), c.in(n, "Detail", 'f', float3(2)),
                        c.in(n, "Detail Scale", 'f', float3(1)),
                        c.in(n, "Detail Roughness", 'f', float3(0.5f)),
                        c.in(n, "Phase Offset", 'f')};
    std::copy(ins, ins + 7, op.in);
    op.out[0] = color;
    op.out[1] = fac;
    op.i[0] = static_cast<int>(p.type);
    op.i[1] = static_cast<int>(p.bands_direction);
    op.i[2] = static_cast<int>(p.rings_direction);
    op.i[3] = static_cast<int>(p.profile);
    c.emit(op);
    c.set_out(n, "Color", color);
    c.set_out(n, "Fac", fac);
}

void magic(Compiler& c, int n) {
    const int color = c.fresh(), fac = c.fresh();
    Op op;
    op.fn = [](const Op& o, R r, G) {
        MagicTextureInputs in;
        in.vector = r[o.in[0]];
        in.scale = r[o.in[1]].x;
        in.distortion = r[o.in[2]].x;
        MagicTextureParams p;
        p.turbulence_depth = o.i[0];
        const MagicTextureOutput out = magic_texture(in, p);
        r[o.out[0]] = out.color;
        r[o.out[1]] = float3(out.fac, 0, 0);
    };
    op.in[0] = tex_vector(c, n, kRegGenerated);
    op.in[1] = c.in(n, "Scale", 'f', float3(5));
    op.in[2] = c.in(n, "Distortion", 'f', float3(1));
    op.out[0] = color;
    op.out[1] = fac;
    op.i[0] = std::clamp(static_cast<int>(c.number_prop(n, "turbulence_depth", 2)), 0, 10);
    c.emit(op);
    c.set_out(n, "Color", color);
    c.set_out(n, "Fac", fac);
}

void gradient(Compiler& c, int n) {
    const std::string t = c.enum_prop(n, "gradient_type", "LINEAR");
    GradientType type = GradientType::LINEAR;
    if (t == "QUADRATIC") type = GradientType::QUADRATIC;
    else if (t == "EASING") type = GradientType::EASING;
    else if (t == "DIAGONAL") type = GradientType::DIAGONAL;
    else if (t == "SPHERICAL") type = GradientType::SPHERICAL;
    else if (t == "QUADRATIC_SPHERE") type = GradientType::QUADRATIC_SPHERE;
    else if (t == "RADIAL") type = GradientType::RADIAL;
    const int color = c.fresh(), fac = c.fresh();
    Op op;
    op.fn = [](const Op& o, R r, G) {
        GradientTextureInputs in;
        in.vector = r[o.in[0]];
        GradientTextureParams p;
        p.type = static_cast<GradientType>(o.i[0]);
        const GradientTextureOutput out = gradient_texture(in, p);
        r[o.out[0]] = out.color;
        r[o.out[1]] = float3(out.fac, 0, 0);
    };
    op.in[0] = tex_vector(c, n, kRegGenerated);
    op.out[0] = color;
    op.out[1] = fac;
    op.i[0] = static_cast<int>(type);
    c.emit(op);
    c.set_out(n, "Color", color);
    c.set_out(n, "Fac", fac);
}

void checker(Compiler& c, int n) {
    const int color = c.fresh(), fac = c.fresh();
    Op op;
    op.fn = [](const Op& o, R r, G) {
        CheckerTextureInputs in;
        in.vector = r[o.in[0]];
        in.color1 = r[o.in[1]];
        in.color2 = r[o.in[2]];
        in.scale = r[o.in[3]].x;
        const CheckerTextureOutput out = checker_texture(in);
        r[o.out[0]] = out.color;
        r[o.out[1]] = float3(out.fac, 0, 0);
    };
    op.in[0] = tex_vector(c, n, kRegGenerated);
    op.in[1] = c.in(n, "Color1", 'c', float3(0.8f));
    op.in[2] = c.in(n, "Color2", 'c', float3(0.2f));
    op.in[3] = c.in(n, "Scale", 'f', float3(5));
    op.out[0] = color;
    op.out[1] = fac;
    c.emit(op);
    c.set_out(n, "Color", color);
    c.set_out(n, "Fac", fac);
}

void brick(Compiler& c, int n) {
    const int color = c.fresh(), fac = c.fresh();
    Op op;
    op.fn = [](const Op& o, R r, G) {
        BrickTextureInputs in;
        in.vector = r[o.in[0]];
        in.color1 = r[o.in[1]];
        in.color2 = r[o.in[2]];
        in.mortar = r[o.in[3]];
        in.scale = r[o.in[4]].x;
        in.mortar_size = r[o.in[5]].x;
        in.mortar_smooth = r[o.in[6]].x;
        in.bias = r[o.in[7]].x;
        in.brick_width = r[o.in[8]].x;
        in.row_height = r[o.in[9]].x;
        BrickTextureParams p;
        p.offset = o.f[0];
        p.offset_frequency = o.i[0];
        p.squash = o.f[1];
        p.squash_frequency = o.i[1];
        const BrickTextureOutput out = brick_texture(in, p);
        r[o.out[0]] = out.color;
        r[o.out[1]] = float3(out.fac, 0, 0);
    };
    const int ins[10] = {tex_vector(c, n, kRegGenerated), c.in(n, "Color1", 'c', float3(0.8f)),
                         c.in(n, "Color2", 'c', float3(0.2f)), c.in(n, "Mortar", 'c'),
                         c.in(n, "Scale", 'f', float3(5)), c.in(n, "Mortar Size", 'f', float3(0.02f)),
                         c.in(n, "Mortar Smooth", 'f', float3(0.1f)), c.in(n, "Bias", 'f'),
                         c.in(n, "Brick Width", 'f', float3(0.5f)),
                         c.in(n, "Row Height", 'f', float3(0.25f))};
    std::copy(ins, ins + 10, op.in);
    op.out[0] = color;
    op.out[1] = fac;
    op.f[0] = static_cast<float>(c.number_prop(n, "offset", 0.5));
    op.i[0] = std::max(1, static_cast<int>(c.number_prop(n, "offset_frequency", 2)));
    op.f[1] = static_cast<float>(c.number_prop(n, "squash", 1.0));
    op.i[1] = std::max(1, static_cast<int>(c.number_prop(n, "squash_frequency", 2)));
    c.emit(op);
    c.set_out(n, "Color", color);
    c.set_out(n, "Fac", fac);
}

float3 vec_prop(Compiler& c, int n, const char* key, float3 fallback) {
    const scene::ShaderProp* p = c.node(n).prop(key);
    if (!p || p->numbers.size() < 3) return fallback;
    return float3(static_cast<float>(p->numbers[0]), static_cast<float>(p->numbers[1]),
                  static_cast<float>(p->numbers[2]));
}

void sky(Compiler& c, int n) {
    SkyParams p;
    const std::string type = c.enum_prop(n, "sky_type", "NISHITA");
    if (!parse_sky_type(type, &p.type)) c.unsupported(n, "sky type " + type + ": Nishita used");
    p.sun_direction = vec_prop(c, n, "sun_direction", p.sun_direction);
    p.turbidity = static_cast<float>(c.number_prop(n, "turbidity", p.turbidity));
    p.ground_albedo = static_cast<float>(c.number_prop(n, "ground_albedo", p.ground_albedo));
    p.sun_disc = c.number_prop(n, "sun_disc", 1) != 0;
    p.sun_size = static_cast<float>(c.number_prop(n, "sun_size", p.sun_size));
    p.sun_intensity = static_cast<float>(c.number_prop(n, "sun_intensity", p.sun_intensity));
    p.sun_elevation = static_cast<float>(c.number_prop(n, "sun_elevation", p.sun_elevation));
    p.sun_rotation = static_cast<float>(c.number_prop(n, "sun_rotation", p.sun_rotation));
    p.altitude = static_cast<float>(c.number_prop(n, "altitude", p.altitude));
    p.air_density = static_cast<float>(c.number_prop(n, "air_density", p.air_density));
    p.dust_density = static_cast<float>(c.number_prop(n, "dust_density", p.dust_density));
    p.ozone_density = static_cast<float>(c.number_prop(n, "ozone_density", p.ozone_density));
    auto model = std::make_shared<SkyModel>(SkyModel::prepare(p));
    const int color = c.fresh();
    Op op;
    op.fn = [](const Op& o, R r, G) {
        r[o.out[0]] = static_cast<const SkyModel*>(o.data)->radiance(r[o.in[0]]);
    };
    op.in[0] = tex_vector(c, n, kRegGenerated);
    op.out[0] = color;
    op.data = model.get();
    c.program_keep(model);
    c.emit(op, false);
    c.set_out(n, "Color", color);
}

// ---------------------------------------------------------------- images

enum Extension { kRepeat, kExtend, kClip, kMirror };

// An image as Cycles 3.4 samples it (kernel/svm/image.h, scene/image.cpp): an 8-bit sRGB
// file stays in its sRGB bytes (compress_as_srgb), premultiplied by alpha in bytes,
// (c * a) / 255 truncated, as Blender's loader does, interpolated there and decoded to
// linear after; other images are linear, premultiplied in floats. Colour data (Non-Color),
// Channel Packed and None alpha are not premultiplied (None: alpha 1). The Color output is
// the premultiplied colour unless the node's Alpha output is linked: then it is divided by
// the interpolated alpha (when that is neither 0 nor 1).
struct ImageRef {
    const ImageTexture* image = nullptr;
    int extension = kRepeat;
    bool closest = false;
    bool srgb_bytes = false;   // the sRGB bytes as stored (decoded after interpolation)
    bool associate = true;     // premultiply by alpha
    bool unassociate = false;  // divide the result by its alpha (Alpha output linked)
    bool ignore_alpha = false; // alpha 1 (alpha mode None)
};

// Texel (x, y) counted from the bottom row, by the extension mode; false outside for Clip.
bool texel(const ImageRef& ref, int x, int y, float4* out) {
    const ImageTexture& im = *ref.image;
    const int w = im.width(), h = im.height();
    auto wrap = [&](int v, int size) {
        switch (ref.extension) {
            case kRepeat: {
                int m = v % size;
                return m < 0 ? m + size : m;
            }
            case kMirror: {
                const int period = 2 * size;
                int m = v % period;
                if (m < 0) m += period;
                return m < size ? m : period - 1 - m;
            }
            default: return std::clamp(v, 0, size - 1);
        }
    };
    if (ref.extension == kClip && (x < 0 || y < 0 || x >= w || y >= h)) {
        *out = float4{0, 0, 0, 0};
        return false;
    }
    const float* t = im.texel(wrap(x, w), h - 1 - wrap(y, h));
    const float alpha = ref.ignore_alpha ? 1.0f : 1.0f - t[4];
    if (ref.srgb_bytes) {
        const int a8 = static_cast<int>(std::lround(alpha * 255.0f));
        int c8[3];
        for (int k = 0; k < 3; ++k) {
            c8[k] = static_cast<int>(std::lround(std::clamp(t[k], 0.0f, 1.0f) * 255.0f));
            if (ref.associate) c8[k] = c8[k] * a8 / 255;
        }
        const float f = 1.0f / 255.0f;
        *out = float4{c8[0] * f, c8[1] * f, c8[2] * f, a8 * f};
        return true;
    }
    const float m = ref.associate ? alpha : 1.0f;
    *out = float4{t[0] * m, t[1] * m, t[2] * m, alpha};
    return true;
}

// Cycles' color_srgb_to_linear.
float srgb_to_linear(float c) {
    if (c < 0.04045f) return c < 0.0f ? 0.0f : c * (1.0f / 12.92f);
    return std::pow((c + 0.055f) * (1.0f / 1.055f), 2.4f);
}

// Cycles' image lookup at (u, v), v up: Closest or Linear (Cubic and Smart as Linear), then
// unassociated and decoded as the image wants.
float4 lookup(const ImageRef& ref, float u, float v) {
    const ImageTexture& im = *ref.image;
    const float x = u * im.width(), y = v * im.height();
    float4 s;
    if (ref.closest) {
        texel(ref, static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)), &s);
    } else {
        const float fx = x - 0.5f, fy = y - 0.5f;
        const int ix = static_cast<int>(std::floor(fx)), iy = static_cast<int>(std::floor(fy));
        const float tx = fx - ix, ty = fy - iy;
        float4 a, b, c, d;
        texel(ref, ix, iy, &a);
        texel(ref, ix + 1, iy, &b);
        texel(ref, ix, iy + 1, &c);
        texel(ref, ix + 1, iy + 1, &d);
        auto lerp4 = [](const float4& p, const float4& q, float t) {
            return float4{p.x + (q.x - p.x) * t, p.y + (q.y - p.y) * t, p.z + (q.z - p.z) * t,
                          p.w + (q.w - p.w) * t};
        };
        s = lerp4(lerp4(a, b, tx), lerp4(c, d, tx), ty);
    }
    if (ref.unassociate && s.w != 1.0f && s.w != 0.0f) {
        const float inv = 1.0f / s.w;
        s = float4{s.x * inv, s.y * inv, s.z * inv, s.w};
    }
    if (ref.srgb_bytes) s = float4{srgb_to_linear(s.x), srgb_to_linear(s.y), srgb_to_linear(s.z), s.w};
    return s;
}

// Whether any node reads output `id` of node `n`.
bool output_linked(Compiler& c, int n, const char* id) {
    for (int k = 0; k < c.node_count(); ++k)
        for (const scene::ShaderInput& in : c.node(k).inputs)
            if (in.link.linked() && in.link.node == n && in.link.output == id) return true;
    return false;
}

const ImageRef* open_image(Compiler& c, int n) {
    const scene::ShaderNode& node = c.node(n);
    if (!node.has_image || node.image.path.empty()) {
        c.unsupported(n, "has no image: it renders magenta, as in Cycles");
        return nullptr;
    }
    if (!c.textures()) {
        c.unsupported(n, "images cannot be read here");
        return nullptr;
    }
    const std::string& cs = node.image.colorspace;
    const bool color = cs == "sRGB";
    const bool data = cs == "Non-Color" || cs == "Raw";
    if (!color && !data && cs != "Linear" && cs != "Linear ACES" && cs != "XYZ" && !cs.empty())
        c.unsupported(n, "colour space '" + cs + "' is read as linear");
    scene::PbrMap map;
    map.file = node.image.path;
    map.resolved_path = node.image.path;
    auto ref = std::make_shared<ImageRef>();
    try {
        // An sRGB image is read as stored first: 8-bit files stay in their bytes.
        c.textures()->add_pbr(map, false);
        const ImageTexture* raw = c.textures()->find_pbr(map, false);
        if (color && raw && raw->srgb8()) {
            ref->image = raw;
            ref->srgb_bytes = true;
        } else if (color) {
            c.textures()->add_pbr(map, true);
            ref->image = c.textures()->find_pbr(map, true);
        } else {
            ref->image = raw;
        }
    } catch (const Error& e) {
        c.unsupported(n, std::string("its image cannot be read (") + e.what() +
                             "): it renders magenta, as in Cycles");
        return nullptr;
    }
    if (!ref->image) {
        c.unsupported(n, "its image '" + node.image.path + "' is missing: it renders magenta, "
                         "as in Cycles");
        return nullptr;
    }
    const std::string& am = node.image.alpha_mode;
    ref->associate = !data && am != "CHANNEL_PACKED" && am != "NONE" && am != "PREMUL";
    ref->ignore_alpha = am == "NONE";
    ref->unassociate = !data && am != "CHANNEL_PACKED" && am != "NONE" &&
                       output_linked(c, n, "Alpha");
    const std::string ext = c.enum_prop(n, "extension", "REPEAT");
    ref->extension = ext == "EXTEND" ? kExtend : ext == "CLIP" ? kClip
                   : ext == "MIRROR" ? kMirror : kRepeat;
    ref->closest = c.enum_prop(n, "interpolation", "Linear") == "Closest";
    c.program_keep(ref);
    return ref.get();
}

void magenta(Compiler& c, int n) {
    c.set_out(n, "Color", c.constant(float3(1, 0, 1)));
    c.set_out(n, "Alpha", c.constant(1.0f));
}

void image_texture(Compiler& c, int n) {
    const ImageRef* ref = open_image(c, n);
    if (!ref) return magenta(c, n);
    const std::string projection = c.enum_prop(n, "projection", "FLAT");
    if (projection != "FLAT")
        c.unsupported(n, "projection " + projection + " is not supported yet: FLAT used");
    const int color = c.fresh(), alpha = c.fresh();
    Op op;
    op.fn = [](const Op& o, R r, G) {
        const float3 uv = r[o.in[0]];
        const float4 s = lookup(*static_cast<const ImageRef*>(o.data), uv.x, uv.y);
        r[o.out[0]] = float3(s.x, s.y, s.z);
        r[o.out[1]] = float3(s.w, 0, 0);
    };
    op.in[0] = tex_vector(c, n, kRegUV);
    op.out[0] = color;
    op.out[1] = alpha;
    op.data = ref;
    c.emit(op, false);
    c.set_out(n, "Color", color);
    c.set_out(n, "Alpha", alpha);
}

void environment_texture(Compiler& c, int n) {
    const ImageRef* ref = open_image(c, n);
    if (!ref) return magenta(c, n);
    const std::string projection = c.enum_prop(n, "projection", "EQUIRECTANGULAR");
    if (projection != "EQUIRECTANGULAR")
        c.unsupported(n, "projection " + projection + " is not supported yet: equirectangular "
                         "used");
    const int color = c.fresh(), alpha = c.fresh();
    Op op;
    op.fn = [](const Op& o, R r, G) {
        const float3 d = safe_normalize(r[o.in[0]]);
        // Cycles' direction_to_equirectangular over the whole sphere.
        const float u = -std::atan2(d.y, d.x) / (2.0f * 3.14159265f) + 0.5f;
        const float v = std::atan2(d.z, std::hypot(d.x, d.y)) / 3.14159265f + 0.5f;
        const float4 s = lookup(*static_cast<const ImageRef*>(o.data), u, v);
        r[o.out[0]] = float3(s.x, s.y, s.z);
        r[o.out[1]] = float3(s.w, 0, 0);
    };
    op.in[0] = tex_vector(c, n, kRegGenerated);
    op.out[0] = color;
    op.out[1] = alpha;
    op.data = ref;
    c.emit(op, false);
    c.set_out(n, "Color", color);
    c.set_out(n, "Alpha", alpha);
}

}  // namespace

void add_texture_nodes(NodeTables& t) {
    t.values["ShaderNodeTexNoise"] = noise;
    t.values["ShaderNodeTexWhiteNoise"] = white_noise;
    t.values["ShaderNodeTexMusgrave"] = musgrave;
    t.values["ShaderNodeTexVoronoi"] = voronoi;
    t.values["ShaderNodeTexWave"] = wave;
    t.values["ShaderNodeTexMagic"] = magic;
    t.values["ShaderNodeTexGradient"] = gradient;
    t.values["ShaderNodeTexChecker"] = checker;
    t.values["ShaderNodeTexBrick"] = brick;
    t.values["ShaderNodeTexSky"] = sky;
    t.values["ShaderNodeTexImage"] = image_texture;
    t.values["ShaderNodeTexEnvironment"] = environment_texture;
}

}  // namespace glint::render::shader
