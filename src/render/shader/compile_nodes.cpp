// Value nodes: inputs (Texture Coordinate, Geometry, Object Info, Light Path, ...), converters
// (Math, Vector Math, Map Range, Clamp, separate/combine, Blackbody, Wavelength), colour
// (Mix, Hue/Saturation, ColorRamp, curves, ...) and vector (Mapping, Vector Rotate) nodes.
// Socket identifiers and settings are Blender 3.4's (formats/blender/FORMAT.md).
#include <algorithm>
#include <cmath>
#include <span>

#include "render/shader/color_nodes.h"
#include "render/shader/compiler.h"
#include "render/shader/converter_nodes.h"
#include "render/shader/vector_nodes.h"

namespace glint::render::shader {

namespace {

using R = float3*;
using G = const ShaderGlobals&;

// Sets output `id` to a register the caller already has (globals, folded values).
void alias(Compiler& c, int node, const char* id, int reg) { c.set_out(node, id, reg); }

// An op of one function over up to 12 inputs into up to 6 outputs.
Op make(void (*fn)(const Op&, R, G), std::initializer_list<int> ins,
        std::initializer_list<int> outs) {
    Op op;
    op.fn = fn;
    int k = 0;
    for (int r : ins) op.in[k++] = r;
    k = 0;
    for (int r : outs) op.out[k++] = r;
    return op;
}

template <typename E>
E parse_or(Compiler& c, int node, const char* key, bool (*parse)(std::string_view, E*),
           E fallback) {
    const std::string text = c.enum_prop(node, key, "");
    E e = fallback;
    if (!text.empty() && !parse(text, &e))
        c.unsupported(node, std::string(key) + " '" + text + "' is not supported: using the default");
    return e;
}

// ---------------------------------------------------------------- inputs

void tex_coord(Compiler& c, int n) {
    if (!c.enum_prop(n, "object", "").empty())
        c.unsupported(n, "coordinates from another object are not supported: the object's own");
    alias(c, n, "Generated", kRegGenerated);
    alias(c, n, "UV", kRegUV);
    alias(c, n, "Object", kRegObject);
    alias(c, n, "Camera", kRegCamera);
    alias(c, n, "Window", kRegWindow);
    alias(c, n, "Reflection", kRegReflection);
    // The object-space normal: the world normal through the transpose of object -> world.
    const int out = c.fresh();
    Op op = make([](const Op& o, R r, G sg) {
        const float3 nw = r[o.in[0]];
        float3 v;
        for (int i = 0; i < 3; ++i)
            v[i] = sg.object_to_world[0][i] * nw.x + sg.object_to_world[1][i] * nw.y +
                   sg.object_to_world[2][i] * nw.z;
        r[o.out[0]] = safe_normalize(v);
    }, {kRegN}, {out});
    c.emit(op, false);
    alias(c, n, "Normal", out);
}

void geometry(Compiler& c, int n) {
    alias(c, n, "Position", kRegP);
    alias(c, n, "Normal", kRegN);
    alias(c, n, "Tangent", kRegTangent);
    alias(c, n, "True Normal", kRegNg);
    alias(c, n, "Incoming", kRegI);
    alias(c, n, "Backfacing", kRegBackfacing);
    alias(c, n, "Parametric", kRegUV);
    alias(c, n, "Pointiness", c.constant(0.5f));
    alias(c, n, "Random Per Island", c.constant(0.0f));
}

// Attribute lookups (Attribute, Color Attribute, UV Map): the mesh's named layer at the hit,
// interpolated over the face; zero (alpha 0) where the mesh has none, as in Cycles.
struct AttributeRequest {
    std::string name;
    AttributeSource::Want want;
};

int attribute_op(Compiler& c, const std::string& name, AttributeSource::Want want, int* alpha) {
    auto req = std::make_shared<AttributeRequest>(AttributeRequest{name, want});
    const int value = c.fresh();
    *alpha = c.fresh();
    Op op = make([](const Op& o, R r, G sg) {
        const auto* q = static_cast<const AttributeRequest*>(o.data);
        Vec3 v;
        double a = 0;
        const AttributePoint& at = sg.attributes;
        if (sg.grids && q->want == AttributeSource::Want::Any &&
            sg.grids->grid(q->name, sg.P.to_vec3(), &v)) {
            a = 1;  // a Volume object's grid
        } else if (!at.source ||
                   !at.source->attribute(q->name, q->want, at.face, at.b1, at.b2, &v, &a)) {
            v = Vec3();
            a = 0;
        }
        r[o.out[0]] = float3(v);
        r[o.out[1]] = float3(static_cast<float>(a), 0, 0);
    }, {}, {value, *alpha});
    op.data = req.get();
    c.program_keep(req);
    c.emit(op, false);
    return value;
}

void uv_map(Compiler& c, int n) {
    if (c.number_prop(n, "from_instancer", 0) != 0)
        c.unsupported(n, "UVs from the instancer are not supported: the object's own");
    const std::string name = c.enum_prop(n, "uv_map", "");
    if (name.empty()) {
        alias(c, n, "UV", kRegUV);
        return;
    }
    int alpha;
    alias(c, n, "UV", attribute_op(c, name, AttributeSource::Want::UV, &alpha));
}

void color_attribute(Compiler& c, int n) {
    int alpha;
    alias(c, n, "Color",
          attribute_op(c, c.enum_prop(n, "layer_name", ""), AttributeSource::Want::Color, &alpha));
    alias(c, n, "Alpha", alpha);
}

void attribute(Compiler& c, int n) {
    const std::string type = c.enum_prop(n, "attribute_type", "GEOMETRY");
    if (type != "GEOMETRY")
        c.unsupported(n, "attributes of type " + type + " are not supported: zero");
    int alpha;
    const int value =
        attribute_op(c, c.enum_prop(n, "attribute_name", ""), AttributeSource::Want::Any, &alpha);
    const int fac = c.fresh();
    c.emit(make([](const Op& o, R r, G) {
        const float3 v = r[o.in[0]];
        r[o.out[0]] = float3((v.x + v.y + v.z) / 3.0f, 0, 0);
    }, {value}, {fac}), false);
    alias(c, n, "Color", value);
    alias(c, n, "Vector", value);
    alias(c, n, "Fac", fac);
    alias(c, n, "Alpha", alpha);
}

void object_info(Compiler& c, int n) {
    alias(c, n, "Location", kRegObjectLocation);
    alias(c, n, "Color", kRegObjectColor);
    const int idx = c.fresh(), rnd = c.fresh(), alpha = c.fresh();
    c.emit(make([](const Op& o, R r, G) {
        r[o.out[0]] = float3(r[o.in[0]].x, 0, 0);
        r[o.out[1]] = float3(r[o.in[0]].y, 0, 0);
        r[o.out[2]] = float3(1, 0, 0);
    }, {kRegObjectInfo}, {idx, rnd, alpha}), false);
    alias(c, n, "Object Index", idx);
    alias(c, n, "Random", rnd);
    alias(c, n, "Alpha", alpha);
    alias(c, n, "Material Index", c.constant(0.0f));
}

// One component of a register as a float output.
int component(Compiler& c, int reg, int k) {
    const int out = c.fresh();
    Op op = make([](const Op& o, R r, G) { r[o.out[0]] = float3(r[o.in[0]][o.i[0]], 0, 0); },
                 {reg}, {out});
    op.i[0] = k;
    c.emit(op, false);
    return out;
}

void light_path(Compiler& c, int n) {
    const struct {
        const char* name;
        int reg, k;
    } outs[] = {{"Is Camera Ray", kRegRay, 0},        {"Is Shadow Ray", kRegRay, 1},
                {"Is Diffuse Ray", kRegRay2, 0},      {"Is Glossy Ray", kRegRay2, 1},
                {"Is Singular Ray", kRegRay2, 2},     {"Is Reflection Ray", kRegRay3, 0},
                {"Is Transmission Ray", kRegRay3, 1}, {"Ray Length", kRegRay, 2},
                {"Ray Depth", kRegRay3, 2},           {"Diffuse Depth", kRegDepths, 0},
                {"Glossy Depth", kRegDepths, 1},      {"Transparent Depth", kRegTransparentDepth, 0},
                {"Transmission Depth", kRegDepths, 2}};
    for (const auto& o : outs) alias(c, n, o.name, component(c, o.reg, o.k));
}

void camera_data(Compiler& c, int n) {
    const int view = c.fresh(), depth = c.fresh();
    c.emit(make([](const Op& o, R r, G) {
        const float3 p = r[o.in[0]];
        r[o.out[0]] = safe_normalize(p);
        r[o.out[1]] = float3(std::fabs(p.z), 0, 0);
    }, {kRegCamera}, {view, depth}), false);
    alias(c, n, "View Vector", view);
    alias(c, n, "View Z Depth", depth);
    alias(c, n, "View Distance", kRegViewDistance);
}

// The output's own value (Value and RGB nodes keep it on their output socket).
void value_node(Compiler& c, int n) {
    for (const scene::ShaderOutput& o : c.node(n).outputs)
        if (o.id == "Value") alias(c, n, "Value", c.constant(static_cast<float>(o.value[0])));
}

void rgb_node(Compiler& c, int n) {
    for (const scene::ShaderOutput& o : c.node(n).outputs)
        if (o.id == "Color")
            alias(c, n, "Color", c.constant(float3(static_cast<float>(o.value[0]),
                                                   static_cast<float>(o.value[1]),
                                                   static_cast<float>(o.value[2]))));
}

// Cycles' fresnel_dielectric_cos: unpolarized reflectance at cosine `cosi`, relative IOR eta.
float fresnel_dielectric_cos(float cosi, float eta) {
    const float cc = std::fabs(cosi);
    float g = eta * eta - 1 + cc * cc;
    if (g > 0) {
        g = std::sqrt(g);
        const float A = (g - cc) / (g + cc);
        const float B = (cc * (g + cc) - 1) / (cc * (g - cc) + 1);
        return 0.5f * A * A * (1 + B * B);
    }
    return 1.0f;
}

int normal_in(Compiler& c, int n, const char* id) {
    return c.linked(n, id) ? c.in(n, id, 'v') : c.normal();
}

void fresnel(Compiler& c, int n) {
    const int out = c.fresh();
    c.emit(make([](const Op& o, R r, G) {
        float eta = std::max(r[o.in[0]].x, 1e-5f);
        eta = r[o.in[3]].x != 0 ? 1.0f / eta : eta;
        r[o.out[0]] = float3(fresnel_dielectric_cos(dot(r[o.in[2]], r[o.in[1]]), eta), 0, 0);
    }, {c.in(n, "IOR", 'f', float3(1.45f)), normal_in(c, n, "Normal"), kRegI, kRegBackfacing},
        {out}), false);
    alias(c, n, "Fac", out);
}

void layer_weight(Compiler& c, int n) {
    const int fr = c.fresh(), facing = c.fresh();
    c.emit(make([](const Op& o, R r, G) {
        float blend = r[o.in[0]].x;
        const float3 N = r[o.in[1]], I = r[o.in[2]];
        float eta = std::max(1.0f - blend, 1e-5f);
        eta = r[o.in[3]].x != 0 ? eta : 1.0f / eta;
        r[o.out[0]] = float3(fresnel_dielectric_cos(dot(I, N), eta), 0, 0);
        float f = std::fabs(dot(I, N));
        if (blend != 0.5f) {
            blend = std::clamp(blend, 0.0f, 1.0f - 1e-5f);
            blend = blend < 0.5f ? 2.0f * blend : 0.5f / (1.0f - blend);
            f = std::pow(f, blend);
        }
        r[o.out[1]] = float3(1.0f - f, 0, 0);
    }, {c.in(n, "Blend", 'f', float3(0.5f)), normal_in(c, n, "Normal"), kRegI, kRegBackfacing},
        {fr, facing}), false);
    alias(c, n, "Fresnel", fr);
    alias(c, n, "Facing", facing);
}

// ---------------------------------------------------------------- converters

void math(Compiler& c, int n) {
    const MathOp m = parse_or(c, n, "operation", parse_math_op, MathOp::ADD);
    const int out = c.fresh();
    Op op = make([](const Op& o, R r, G) {
        r[o.out[0]] = float3(math_node(static_cast<MathOp>(o.i[0]), r[o.in[0]].x, r[o.in[1]].x,
                                       r[o.in[2]].x, o.i[1] != 0), 0, 0);
    }, {c.in(n, "Value", 'f', float3(0.5f)), c.in(n, "Value_001", 'f', float3(0.5f)),
        c.in(n, "Value_002", 'f', float3(0.5f))}, {out});
    op.i[0] = static_cast<int>(m);
    op.i[1] = c.number_prop(n, "use_clamp", 0) != 0;
    c.emit(op);
    alias(c, n, "Value", out);
}

void vector_math(Compiler& c, int n) {
    const VectorMathOp m = parse_or(c, n, "operation", parse_vector_math_op, VectorMathOp::ADD);
    const int vec = c.fresh(), val = c.fresh();
    Op op = make([](const Op& o, R r, G) {
        const VectorMathResult res = vector_math_node(static_cast<VectorMathOp>(o.i[0]),
                                                      r[o.in[0]], r[o.in[1]], r[o.in[2]],
                                                      r[o.in[3]].x);
        r[o.out[0]] = res.vector;
        r[o.out[1]] = float3(res.value, 0, 0);
    }, {c.in(n, "Vector", 'v'), c.in(n, "Vector_001", 'v'), c.in(n, "Vector_002", 'v'),
        c.in(n, "Scale", 'f', float3(1.0f))}, {vec, val});
    op.i[0] = static_cast<int>(m);
    c.emit(op);
    alias(c, n, "Vector", vec);
    alias(c, n, "Value", val);
}

void map_range(Compiler& c, int n) {
    const MapRangeInterpolation t = parse_or(c, n, "interpolation_type",
                                             parse_map_range_interpolation,
                                             MapRangeInterpolation::LINEAR);
    const bool vector = c.enum_prop(n, "data_type", "FLOAT") == "FLOAT_VECTOR";
    const bool clamp = c.number_prop(n, "clamp", 1) != 0;
    const int out = c.fresh();
    Op op;
    if (vector) {
        op = make([](const Op& o, R r, G) {
            r[o.out[0]] = map_range_vector_node(static_cast<MapRangeInterpolation>(o.i[0]),
                                                r[o.in[0]], r[o.in[1]], r[o.in[2]], r[o.in[3]],
                                                r[o.in[4]], r[o.in[5]], o.i[1] != 0);
        }, {c.in(n, "Vector", 'v'), c.in(n, "From_Min_FLOAT3", 'v'),
            c.in(n, "From_Max_FLOAT3", 'v', float3(1)), c.in(n, "To_Min_FLOAT3", 'v'),
            c.in(n, "To_Max_FLOAT3", 'v', float3(1)), c.in(n, "Steps_FLOAT3", 'v', float3(4))},
           {out});
    } else {
        op = make([](const Op& o, R r, G) {
            r[o.out[0]] = float3(map_range_node(static_cast<MapRangeInterpolation>(o.i[0]),
                                                r[o.in[0]].x, r[o.in[1]].x, r[o.in[2]].x,
                                                r[o.in[3]].x, r[o.in[4]].x, r[o.in[5]].x,
                                                o.i[1] != 0), 0, 0);
        }, {c.in(n, "Value", 'f', float3(1)), c.in(n, "From Min", 'f'),
            c.in(n, "From Max", 'f', float3(1)), c.in(n, "To Min", 'f'),
            c.in(n, "To Max", 'f', float3(1)), c.in(n, "Steps", 'f', float3(4))}, {out});
    }
    op.i[0] = static_cast<int>(t);
    op.i[1] = clamp;
    c.emit(op);
    alias(c, n, vector ? "Vector" : "Result", out);
}

void clamp_node_fn(Compiler& c, int n) {
    const ClampType t = parse_or(c, n, "clamp_type", parse_clamp_type, ClampType::MINMAX);
    const int out = c.fresh();
    Op op = make([](const Op& o, R r, G) {
        r[o.out[0]] = float3(clamp_node(static_cast<ClampType>(o.i[0]), r[o.in[0]].x,
                                        r[o.in[1]].x, r[o.in[2]].x), 0, 0);
    }, {c.in(n, "Value", 'f', float3(1)), c.in(n, "Min", 'f'), c.in(n, "Max", 'f', float3(1))},
       {out});
    op.i[0] = static_cast<int>(t);
    c.emit(op);
    alias(c, n, "Result", out);
}

// Splits a vector register into three float outputs named `names`.
void split(Compiler& c, int n, int reg, const char* x, const char* y, const char* z) {
    const int a = c.fresh(), b = c.fresh(), d = c.fresh();
    c.emit(make([](const Op& o, R r, G) {
        const float3 v = r[o.in[0]];
        r[o.out[0]] = float3(v.x, 0, 0);
        r[o.out[1]] = float3(v.y, 0, 0);
        r[o.out[2]] = float3(v.z, 0, 0);
    }, {reg}, {a, b, d}));
    alias(c, n, x, a);
    alias(c, n, y, b);
    alias(c, n, z, d);
}

int join(Compiler& c, int x, int y, int z) {
    const int out = c.fresh();
    c.emit(make([](const Op& o, R r, G) {
        r[o.out[0]] = float3(r[o.in[0]].x, r[o.in[1]].x, r[o.in[2]].x);
    }, {x, y, z}, {out}));
    return out;
}

void separate_color(Compiler& c, int n) {
    const ColorMode m = parse_or(c, n, "mode", parse_color_mode, ColorMode::RGB);
    const int out = c.fresh();
    Op op = make([](const Op& o, R r, G) {
        r[o.out[0]] = separate_color_node(static_cast<ColorMode>(o.i[0]), r[o.in[0]]);
    }, {c.in(n, "Color", 'c', float3(0.8f))}, {out});
    op.i[0] = static_cast<int>(m);
    c.emit(op);
    split(c, n, out, "Red", "Green", "Blue");
}

void combine_color(Compiler& c, int n) {
    const ColorMode m = parse_or(c, n, "mode", parse_color_mode, ColorMode::RGB);
    const int out = c.fresh();
    Op op = make([](const Op& o, R r, G) {
        r[o.out[0]] = combine_color_node(static_cast<ColorMode>(o.i[0]), r[o.in[0]].x,
                                         r[o.in[1]].x, r[o.in[2]].x);
    }, {c.in(n, "Red", 'f'), c.in(n, "Green", 'f'), c.in(n, "Blue", 'f')}, {out});
    op.i[0] = static_cast<int>(m);
    c.emit(op);
    alias(c, n, "Color", out);
}

void separate_rgb(Compiler& c, int n) { split(c, n, c.in(n, "Image", 'c', float3(0.8f)), "R", "G", "B"); }
void combine_rgb(Compiler& c, int n) {
    alias(c, n, "Image", join(c, c.in(n, "R", 'f'), c.in(n, "G", 'f'), c.in(n, "B", 'f')));
}
void separate_xyz(Compiler& c, int n) { split(c, n, c.in(n, "Vector", 'v'), "X", "Y", "Z"); }
void combine_xyz(Compiler& c, int n) {
    alias(c, n, "Vector", join(c, c.in(n, "X", 'f'), c.in(n, "Y", 'f'), c.in(n, "Z", 'f')));
}

void separate_hsv(Compiler& c, int n) {
    const int out = c.fresh();
    c.emit(make([](const Op& o, R r, G) { r[o.out[0]] = separate_hsv_node(r[o.in[0]]); },
                {c.in(n, "Color", 'c', float3(0.8f))}, {out}));
    split(c, n, out, "H", "S", "V");
}

void combine_hsv(Compiler& c, int n) {
    const int out = c.fresh();
    c.emit(make([](const Op& o, R r, G) {
        r[o.out[0]] = combine_hsv_node(r[o.in[0]].x, r[o.in[1]].x, r[o.in[2]].x);
    }, {c.in(n, "H", 'f'), c.in(n, "S", 'f'), c.in(n, "V", 'f')}, {out}));
    alias(c, n, "Color", out);
}

void rgb_to_bw(Compiler& c, int n) {
    const int out = c.fresh();
    c.emit(make([](const Op& o, R r, G) { r[o.out[0]] = float3(rgb_to_bw_node(r[o.in[0]]), 0, 0); },
                {c.in(n, "Color", 'c', float3(0.5f))}, {out}));
    alias(c, n, "Val", out);
}

void blackbody(Compiler& c, int n) {
    const int out = c.fresh();
    c.emit(make([](const Op& o, R r, G) { r[o.out[0]] = blackbody_node(r[o.in[0]].x); },
                {c.in(n, "Temperature", 'f', float3(1500))}, {out}));
    alias(c, n, "Color", out);
}

void wavelength(Compiler& c, int n) {
    const int out = c.fresh();
    c.emit(make([](const Op& o, R r, G) { r[o.out[0]] = wavelength_node(r[o.in[0]].x); },
                {c.in(n, "Wavelength", 'f', float3(500))}, {out}));
    alias(c, n, "Color", out);
}

// ---------------------------------------------------------------- colour

void mix_rgb(Compiler& c, int n) {
    const MixBlend b = parse_or(c, n, "blend_type", parse_mix_blend, MixBlend::MIX);
    const int out = c.fresh();
    Op op = make([](const Op& o, R r, G) {
        r[o.out[0]] = mix_rgb_node(static_cast<MixBlend>(o.i[0]), r[o.in[0]].x, r[o.in[1]],
                                   r[o.in[2]], o.i[1] != 0);
    }, {c.in(n, "Fac", 'f', float3(0.5f)), c.in(n, "Color1", 'c', float3(0.5f)),
        c.in(n, "Color2", 'c', float3(0.5f))}, {out});
    op.i[0] = static_cast<int>(b);
    op.i[1] = c.number_prop(n, "use_clamp", 0) != 0;
    c.emit(op);
    alias(c, n, "Color", out);
}

// Blender 3.4's Mix node: float, vector (uniform or per-component factor) or colour.
void mix(Compiler& c, int n) {
    const MixDataType t = parse_or(c, n, "data_type", parse_mix_data_type, MixDataType::RGBA);
    const bool clamp_factor = c.number_prop(n, "clamp_factor", 1) != 0;
    const int out = c.fresh();
    Op op;
    if (t == MixDataType::FLOAT) {
        op = make([](const Op& o, R r, G) {
            r[o.out[0]] = float3(mix_float_node(r[o.in[0]].x, r[o.in[1]].x, r[o.in[2]].x,
                                                o.i[1] != 0), 0, 0);
        }, {c.in(n, "Factor_Float", 'f', float3(0.5f)), c.in(n, "A_Float", 'f'),
            c.in(n, "B_Float", 'f')}, {out});
        alias(c, n, "Result_Float", out);
    } else if (t == MixDataType::VECTOR) {
        const bool uniform = c.enum_prop(n, "factor_mode", "UNIFORM") == "UNIFORM";
        if (uniform)
            op = make([](const Op& o, R r, G) {
                r[o.out[0]] = mix_vector_node(r[o.in[0]].x, r[o.in[1]], r[o.in[2]], o.i[1] != 0);
            }, {c.in(n, "Factor_Float", 'f', float3(0.5f)), c.in(n, "A_Vector", 'v'),
                c.in(n, "B_Vector", 'v')}, {out});
        else
            op = make([](const Op& o, R r, G) {
                r[o.out[0]] = mix_vector_non_uniform_node(r[o.in[0]], r[o.in[1]], r[o.in[2]],
                                                          o.i[1] != 0);
            }, {c.in(n, "Factor_Vector", 'v', float3(0.5f)), c.in(n, "A_Vector", 'v'),
                c.in(n, "B_Vector", 'v')}, {out});
        alias(c, n, "Result_Vector", out);
    } else {
        op = make([](const Op& o, R r, G) {
            r[o.out[0]] = mix_color_node(static_cast<MixBlend>(o.i[0]), r[o.in[0]].x,
                                         r[o.in[1]], r[o.in[2]], o.i[1] != 0, o.i[2] != 0);
        }, {c.in(n, "Factor_Float", 'f', float3(0.5f)), c.in(n, "A_Color", 'c', float3(0.5f)),
            c.in(n, "B_Color", 'c', float3(0.5f))}, {out});
        op.i[0] = static_cast<int>(parse_or(c, n, "blend_type", parse_mix_blend, MixBlend::MIX));
        op.i[2] = c.number_prop(n, "clamp_result", 0) != 0;
        alias(c, n, "Result_Color", out);
    }
    op.i[1] = clamp_factor;
    c.emit(op);
}

void hue_sat(Compiler& c, int n) {
    const int out = c.fresh();
    c.emit(make([](const Op& o, R r, G) {
        r[o.out[0]] = hue_saturation_value_node(r[o.in[0]].x, r[o.in[1]].x, r[o.in[2]].x,
                                                r[o.in[3]].x, r[o.in[4]]);
    }, {c.in(n, "Hue", 'f', float3(0.5f)), c.in(n, "Saturation", 'f', float3(1)),
        c.in(n, "Value", 'f', float3(1)), c.in(n, "Fac", 'f', float3(1)),
        c.in(n, "Color", 'c', float3(0.8f))}, {out}));
    alias(c, n, "Color", out);
}

void bright_contrast(Compiler& c, int n) {
    const int out = c.fresh();
    c.emit(make([](const Op& o, R r, G) {
        r[o.out[0]] = bright_contrast_node(r[o.in[0]], r[o.in[1]].x, r[o.in[2]].x);
    }, {c.in(n, "Color", 'c', float3(1)), c.in(n, "Bright", 'f'), c.in(n, "Contrast", 'f')},
       {out}));
    alias(c, n, "Color", out);
}

void gamma(Compiler& c, int n) {
    const int out = c.fresh();
    c.emit(make([](const Op& o, R r, G) { r[o.out[0]] = gamma_node(r[o.in[0]], r[o.in[1]].x); },
                {c.in(n, "Color", 'c', float3(1)), c.in(n, "Gamma", 'f', float3(1))}, {out}));
    alias(c, n, "Color", out);
}

void invert(Compiler& c, int n) {
    const int out = c.fresh();
    c.emit(make([](const Op& o, R r, G) { r[o.out[0]] = invert_node(r[o.in[0]].x, r[o.in[1]]); },
                {c.in(n, "Fac", 'f', float3(1)), c.in(n, "Color", 'c')}, {out}));
    alias(c, n, "Color", out);
}

const float* keep_table(Compiler& c, const std::vector<float>& table) { return c.keep(table); }

void color_ramp(Compiler& c, int n) {
    const auto& node = c.node(n);
    if (node.ramp.size() != 256 * 4) {
        c.unsupported(n, "has no baked ramp table");
        return;
    }
    const ColorRampInterpolation interp =
        parse_or(c, n, "interpolation", parse_color_ramp_interpolation,
                 ColorRampInterpolation::LINEAR);
    const int col = c.fresh(), alpha = c.fresh();
    Op op = make([](const Op& o, R r, G) {
        const auto* t = static_cast<const float4*>(o.data);
        const float4 v = color_ramp_node(std::span<const float4>(t, 256), r[o.in[0]].x, o.i[0] != 0);
        r[o.out[0]] = float3(v.x, v.y, v.z);
        r[o.out[1]] = float3(v.w, 0, 0);
    }, {c.in(n, "Fac", 'f', float3(0.5f))}, {col, alpha});
    op.i[0] = color_ramp_interpolates(interp);
    op.data = keep_table(c, node.ramp);
    c.emit(op);
    alias(c, n, "Color", col);
    alias(c, n, "Alpha", alpha);
}

// RGB and Vector Curves: three tables, one a channel (RGB's already composed with the
// combined curve, FORMAT.md), packed into one float4 table as Cycles bakes it.
void curves(Compiler& c, int n, bool rgb) {
    const auto& node = c.node(n);
    if (node.curves.size() < 3 || node.curves[0].size() != 256 || node.curves[1].size() != 256 ||
        node.curves[2].size() != 256) {
        c.unsupported(n, "has no baked curve tables");
        return;
    }
    std::vector<float> table(256 * 4, 0.0f);
    for (int i = 0; i < 256; ++i)
        for (int k = 0; k < 3; ++k) table[i * 4 + k] = node.curves[k][i];
    const int out = c.fresh();
    Op op = make([](const Op& o, R r, G) {
        const auto* t = static_cast<const float4*>(o.data);
        const std::span<const float4> s(t, 256);
        r[o.out[0]] = o.i[0] ? rgb_curves_node(s, o.f[0], o.f[1], o.i[1] != 0, r[o.in[0]].x, r[o.in[1]])
                             : vector_curves_node(s, o.f[0], o.f[1], o.i[1] != 0, r[o.in[0]].x,
                                                  r[o.in[1]]);
    }, {c.in(n, "Fac", 'f', float3(1)), c.in(n, rgb ? "Color" : "Vector", rgb ? 'c' : 'v')}, {out});
    op.i[0] = rgb;
    op.i[1] = node.curve_extrapolate;
    op.f[0] = static_cast<float>(node.curve_min);
    op.f[1] = static_cast<float>(node.curve_max);
    op.data = keep_table(c, table);
    c.emit(op);
    alias(c, n, rgb ? "Color" : "Vector", out);
}

void rgb_curves(Compiler& c, int n) { curves(c, n, true); }
void vector_curves(Compiler& c, int n) { curves(c, n, false); }

void float_curve(Compiler& c, int n) {
    const auto& node = c.node(n);
    if (node.curves.empty() || node.curves[0].size() != 256) {
        c.unsupported(n, "has no baked curve table");
        return;
    }
    const int out = c.fresh();
    Op op = make([](const Op& o, R r, G) {
        const auto* t = static_cast<const float*>(o.data);
        r[o.out[0]] = float3(float_curve_node(std::span<const float>(t, 256), o.f[0], o.f[1],
                                              o.i[1] != 0, r[o.in[0]].x, r[o.in[1]].x), 0, 0);
    }, {c.in(n, "Factor", 'f', float3(1)), c.in(n, "Value", 'f', float3(1))}, {out});
    op.i[1] = node.curve_extrapolate;
    op.f[0] = static_cast<float>(node.curve_min);
    op.f[1] = static_cast<float>(node.curve_max);
    op.data = keep_table(c, node.curves[0]);
    c.emit(op);
    alias(c, n, "Value", out);
}

// ---------------------------------------------------------------- vector

void mapping(Compiler& c, int n) {
    const MappingType t = parse_or(c, n, "vector_type", parse_mapping_type, MappingType::POINT);
    const int out = c.fresh();
    Op op = make([](const Op& o, R r, G) {
        r[o.out[0]] = mapping_node(static_cast<MappingType>(o.i[0]), r[o.in[0]], r[o.in[1]],
                                   r[o.in[2]], r[o.in[3]]);
    }, {c.in(n, "Vector", 'v'), c.in(n, "Location", 'v'), c.in(n, "Rotation", 'v'),
        c.in(n, "Scale", 'v', float3(1))}, {out});
    op.i[0] = static_cast<int>(t);
    c.emit(op);
    alias(c, n, "Vector", out);
}

// Displacement and Vector Displacement (svm_node_displacement, svm_node_vector_displacement):
// the offset that the material output turns into a bump. Object space goes through the
// object's transform as Cycles takes it (the normal back by the transpose, normalized; the
// offset forwards, so a scaled object's offset scales with it).
float3 object_dir(const ShaderGlobals& sg, float3 v) {
    float3 w;
    for (int i = 0; i < 3; ++i)
        w[i] = sg.object_to_world[i][0] * v.x + sg.object_to_world[i][1] * v.y +
               sg.object_to_world[i][2] * v.z;
    return w;
}

void displacement(Compiler& c, int n) {
    const bool object = c.enum_prop(n, "space", "OBJECT") == "OBJECT";
    const int out = c.fresh();
    Op op = make([](const Op& o, R r, G sg) {
        const float h = (r[o.in[0]].x - r[o.in[1]].x) * r[o.in[2]].x;
        float3 d = r[o.in[3]];
        if (o.i[0]) {
            float3 back;
            for (int i = 0; i < 3; ++i)
                back[i] = sg.object_to_world[0][i] * d.x + sg.object_to_world[1][i] * d.y +
                          sg.object_to_world[2][i] * d.z;
            d = object_dir(sg, safe_normalize(back) * h);
        } else {
            d = d * h;
        }
        r[o.out[0]] = d;
    }, {c.in(n, "Height", 'f'), c.in(n, "Midlevel", 'f', float3(0.5f)),
        c.in(n, "Scale", 'f', float3(1)), normal_in(c, n, "Normal")}, {out});
    op.i[0] = object;
    c.emit(op, false);
    alias(c, n, "Displacement", out);
}

void vector_displacement(Compiler& c, int n) {
    const std::string space = c.enum_prop(n, "space", "TANGENT");
    if (space == "TANGENT")
        c.unsupported(n, "tangent space is not supported yet: read as object space");
    const int out = c.fresh();
    Op op = make([](const Op& o, R r, G sg) {
        float3 d = (r[o.in[0]] - float3(r[o.in[1]].x)) * r[o.in[2]].x;
        if (o.i[0]) d = object_dir(sg, d);
        r[o.out[0]] = d;
    }, {c.in(n, "Vector", 'c'), c.in(n, "Midlevel", 'f'), c.in(n, "Scale", 'f', float3(1))},
       {out});
    op.i[0] = space != "WORLD";
    c.emit(op, false);
    alias(c, n, "Displacement", out);
}

void vector_rotate(Compiler& c, int n) {
    const VectorRotateType t = parse_or(c, n, "rotation_type", parse_vector_rotate_type,
                                        VectorRotateType::AXIS_ANGLE);
    const int out = c.fresh();
    Op op = make([](const Op& o, R r, G) {
        r[o.out[0]] = vector_rotate_node(static_cast<VectorRotateType>(o.i[0]), r[o.in[0]],
                                         r[o.in[1]], r[o.in[2]], r[o.in[3]].x, r[o.in[4]],
                                         o.i[1] != 0);
    }, {c.in(n, "Vector", 'v'), c.in(n, "Center", 'v'), c.in(n, "Axis", 'v', float3(0, 0, 1)),
        c.in(n, "Angle", 'f'), c.in(n, "Rotation", 'v')}, {out});
    op.i[0] = static_cast<int>(t);
    op.i[1] = c.number_prop(n, "invert", 0) != 0;
    c.emit(op);
    alias(c, n, "Vector", out);
}

// Vector Transform between world, object and camera space, as Cycles 3.4 does it
// (svm/vector_transform.h): through the world, a normal moved as a direction (the matrices
// themselves, not their inverse transposes) and normalized.
enum Space { kWorld, kObject, kCamera };

void vector_transform(Compiler& c, int n) {
    const std::string type = c.enum_prop(n, "vector_type", "VECTOR");
    auto space = [&](const char* key, const char* fallback) {
        const std::string s = c.enum_prop(n, key, fallback);
        return s == "OBJECT" ? kObject : s == "CAMERA" ? kCamera : kWorld;
    };
    const int out = c.fresh();
    Op op = make([](const Op& o, R r, G sg) {
        float3 v = r[o.in[0]];
        const bool dir = o.i[0] != 0;
        auto apply = [&](const float (&m)[3][4]) {
            float3 res;
            for (int i = 0; i < 3; ++i)
                res[i] = m[i][0] * v.x + m[i][1] * v.y + m[i][2] * v.z + (dir ? 0 : m[i][3]);
            v = res;
        };
        const int from = o.i[1], to = o.i[2];
        if (from == kWorld) {
            if (to == kCamera) apply(sg.world_to_camera);
            else if (to == kObject) apply(sg.world_to_object);
        } else if (from == kCamera) {
            if (to != kCamera) apply(sg.camera_to_world);
            if (to == kObject) apply(sg.world_to_object);
        } else {
            if (to != kObject) apply(sg.object_to_world);
            if (to == kCamera) apply(sg.world_to_camera);
        }
        r[o.out[0]] = o.i[0] == 2 ? safe_normalize(v) : v;
    }, {c.in(n, "Vector", 'v')}, {out});
    op.i[0] = type == "POINT" ? 0 : (type == "NORMAL" ? 2 : 1);
    op.i[1] = space("convert_from", "WORLD");
    op.i[2] = space("convert_to", "OBJECT");
    if (op.i[1] == op.i[2] && op.i[0] != 2) {
        alias(c, n, "Vector", op.in[0]);
        return;
    }
    c.emit(op, false);
    alias(c, n, "Vector", out);
}

}  // namespace

void add_basic_nodes(NodeTables& t) {
    auto& v = t.values;
    v["ShaderNodeTexCoord"] = tex_coord;
    v["ShaderNodeNewGeometry"] = geometry;
    v["ShaderNodeUVMap"] = uv_map;
    v["ShaderNodeVertexColor"] = color_attribute;
    v["ShaderNodeAttribute"] = attribute;
    v["ShaderNodeObjectInfo"] = object_info;
    v["ShaderNodeLightPath"] = light_path;
    v["ShaderNodeCameraData"] = camera_data;
    v["ShaderNodeValue"] = value_node;
    v["ShaderNodeRGB"] = rgb_node;
    v["ShaderNodeFresnel"] = fresnel;
    v["ShaderNodeLayerWeight"] = layer_weight;
    v["ShaderNodeMath"] = math;
    v["ShaderNodeVectorMath"] = vector_math;
    v["ShaderNodeMapRange"] = map_range;
    v["ShaderNodeClamp"] = clamp_node_fn;
    v["ShaderNodeSeparateColor"] = separate_color;
    v["ShaderNodeCombineColor"] = combine_color;
    v["ShaderNodeSeparateRGB"] = separate_rgb;
    v["ShaderNodeCombineRGB"] = combine_rgb;
    v["ShaderNodeSeparateXYZ"] = separate_xyz;
    v["ShaderNodeCombineXYZ"] = combine_xyz;
    v["ShaderNodeSeparateHSV"] = separate_hsv;
    v["ShaderNodeCombineHSV"] = combine_hsv;
    v["ShaderNodeRGBToBW"] = rgb_to_bw;
    v["ShaderNodeBlackbody"] = blackbody;
    v["ShaderNodeWavelength"] = wavelength;
    v["ShaderNodeMixRGB"] = mix_rgb;
    v["ShaderNodeMix"] = mix;
    v["ShaderNodeHueSaturation"] = hue_sat;
    v["ShaderNodeBrightContrast"] = bright_contrast;
    v["ShaderNodeGamma"] = gamma;
    v["ShaderNodeInvert"] = invert;
    v["ShaderNodeValToRGB"] = color_ramp;
    v["ShaderNodeRGBCurve"] = rgb_curves;
    v["ShaderNodeVectorCurve"] = vector_curves;
    v["ShaderNodeFloatCurve"] = float_curve;
    v["ShaderNodeMapping"] = mapping;
    v["ShaderNodeVectorRotate"] = vector_rotate;
    v["ShaderNodeDisplacement"] = displacement;
    v["ShaderNodeVectorDisplacement"] = vector_displacement;
    v["ShaderNodeVectorTransform"] = vector_transform;
}

}  // namespace glint::render::shader
