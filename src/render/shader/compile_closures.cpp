// Shader nodes (BSDFs, Emission, Background, Transparent, Holdout, Mix and Add Shader) into
// the closure tree, and the nodes that bend normals (Bump, Normal Map). BSDFs glint does not
// have yet are warned and drawn as the nearest one it has.
#include <algorithm>
#include <cmath>

#include "render/shader/compiler.h"

namespace glint::render::shader {

namespace {

using R = float3*;
using G = const ShaderGlobals&;

int normal_in(Compiler& c, int n, const char* id = "Normal") {
    return c.linked(n, id) ? c.in(n, id, 'v') : c.normal();
}

using S = ClosureNode;

ClosureNode bsdf_node(ClosureKind kind, std::initializer_list<std::pair<int, int>> slots) {
    ClosureNode node;
    node.kind = ClosureNode::Kind::Bsdf;
    node.bsdf = kind;
    for (const auto& [slot, reg] : slots) node.in[slot] = reg;
    return node;
}

// The node's `distribution` as Cycles 3.4 takes it; SHARP (and a constant roughness of 0,
// which Cycles simplifies to SHARP) give no roughness register.
Distribution distribution(Compiler& c, int n, const char* fallback, bool* sharp) {
    const std::string d = c.enum_prop(n, "distribution", fallback);
    *sharp = d == "SHARP";
    if (d == "BECKMANN") return Distribution::Beckmann;
    if (d == "ASHIKHMIN_SHIRLEY") return Distribution::AshikhminShirley;
    if (d == "MULTI_GGX") return Distribution::MultiGGX;
    return Distribution::GGX;
}

int diffuse(Compiler& c, int n) {
    return c.add_closure(bsdf_node(ClosureKind::Diffuse,
                                   {{S::kColor, c.in(n, "Color", 'c', float3(0.8f))},
                                    {S::kNormal, normal_in(c, n)},
                                    {S::kRoughness, c.in(n, "Roughness", 'f')}}));
}

// The node's subsurface_method (Principled) or falloff (Subsurface Scattering).
SubsurfaceMethod subsurface_method(Compiler& c, int n, const char* key) {
    const std::string m = c.enum_prop(n, key, "RANDOM_WALK");
    if (m == "RANDOM_WALK_FIXED_RADIUS") return SubsurfaceMethod::FixedRadius;
    if (m == "BURLEY") {
        c.unsupported(n, "Christensen-Burley subsurface is drawn as Random Walk (Fixed Radius)");
        return SubsurfaceMethod::Burley;
    }
    return SubsurfaceMethod::RandomWalk;
}

int principled(Compiler& c, int n) {
    bool sharp = false;
    ClosureNode node = bsdf_node(
        ClosureKind::Principled,
        {{S::kColor, c.in(n, "Base Color", 'c', float3(0.8f))},
         {S::kNormal, normal_in(c, n)},
         {S::kRoughness, c.in(n, "Roughness", 'f', float3(0.5f))},
         {S::kIor, c.in(n, "IOR", 'f', float3(1.45f))},
         {S::kMetallic, c.in(n, "Metallic", 'f')},
         {S::kSpecular, c.in(n, "Specular", 'f', float3(0.5f))},
         {S::kTransmission, c.in(n, "Transmission", 'f')},
         {S::kAlpha, c.in(n, "Alpha", 'f', float3(1))},
         {S::kEmission, c.in(n, "Emission", 'c')},
         {S::kEmissionStrength, c.in(n, "Emission Strength", 'f', float3(1))},
         {S::kSpecularTint, c.in(n, "Specular Tint", 'f')},
         {S::kAnisotropy, c.in(n, "Anisotropic", 'f')},
         {S::kRotation, c.in(n, "Anisotropic Rotation", 'f')},
         {S::kSheen, c.in(n, "Sheen", 'f')},
         {S::kSheenTint, c.in(n, "Sheen Tint", 'f', float3(0.5f))},
         {S::kClearcoat, c.in(n, "Clearcoat", 'f')},
         {S::kClearcoatRoughness, c.in(n, "Clearcoat Roughness", 'f', float3(0.03f))},
         {S::kClearcoatNormal, normal_in(c, n, "Clearcoat Normal")},
         {S::kTransmissionRoughness, c.in(n, "Transmission Roughness", 'f')},
         {S::kTangent, c.linked(n, "Tangent") ? c.in(n, "Tangent", 'v')
                                              : static_cast<int>(kRegTangent)},
         {S::kSubsurface, c.in(n, "Subsurface", 'f')},
         {S::kSubsurfaceRadius, c.in(n, "Subsurface Radius", 'v', float3(1, 0.2f, 0.1f))},
         {S::kSubsurfaceColor, c.in(n, "Subsurface Color", 'c', float3(0.8f))},
         {S::kSubsurfaceIor, c.in(n, "Subsurface IOR", 'f', float3(1.4f))},
         {S::kSubsurfaceAnisotropy, c.in(n, "Subsurface Anisotropy", 'f')}});
    node.distribution = distribution(c, n, "GGX", &sharp);
    node.subsurface = subsurface_method(c, n, "subsurface_method");
    return c.add_closure(node);
}

// The Subsurface Scattering node: a BSSRDF of its colour, radius x scale, IOR, anisotropy.
int subsurface(Compiler& c, int n) {
    ClosureNode node = bsdf_node(
        ClosureKind::Subsurface,
        {{S::kColor, c.in(n, "Color", 'c', float3(0.8f))},
         {S::kNormal, normal_in(c, n)},
         {S::kSubsurface, c.in(n, "Scale", 'f', float3(1))},
         {S::kSubsurfaceRadius, c.in(n, "Radius", 'v', float3(1, 0.2f, 0.1f))},
         {S::kSubsurfaceIor, c.in(n, "IOR", 'f', float3(1.4f))},
         {S::kSubsurfaceAnisotropy, c.in(n, "Anisotropy", 'f')}});
    node.subsurface = subsurface_method(c, n, "falloff");
    return c.add_closure(node);
}

// Glossy and Anisotropic: microfacet reflection tinted by the colour.
int glossy(Compiler& c, int n) {
    bool sharp = false;
    const bool aniso = c.node(n).type == "ShaderNodeBsdfAnisotropic";
    ClosureNode node = bsdf_node(
        ClosureKind::Glossy,
        {{S::kColor, c.in(n, "Color", 'c', float3(0.8f))},
         {S::kNormal, normal_in(c, n)}});
    node.distribution = distribution(c, n, "GGX", &sharp);
    node.in[S::kRoughness] = sharp ? c.constant(0.0f) : c.in(n, "Roughness", 'f', float3(0.5f));
    if (aniso) {
        node.in[S::kAnisotropy] = c.in(n, "Anisotropy", 'f', float3(0.5f));
        node.in[S::kRotation] = c.in(n, "Rotation", 'f');
        node.in[S::kTangent] =
            c.linked(n, "Tangent") ? c.in(n, "Tangent", 'v') : static_cast<int>(kRegTangent);
    }
    return c.add_closure(node);
}

// Glass and Refraction (Blender's default distribution for both is Beckmann).
int glass(Compiler& c, int n) {
    bool sharp = false;
    const ClosureKind kind = c.node(n).type == "ShaderNodeBsdfRefraction"
                                 ? ClosureKind::Refraction : ClosureKind::Glass;
    ClosureNode node = bsdf_node(kind, {{S::kColor, c.in(n, "Color", 'c', float3(1))},
                                        {S::kNormal, normal_in(c, n)},
                                        {S::kIor, c.in(n, "IOR", 'f', float3(1.45f))}});
    node.distribution = distribution(c, n, "BECKMANN", &sharp);
    node.in[S::kRoughness] = sharp ? c.constant(0.0f) : c.in(n, "Roughness", 'f');
    return c.add_closure(node);
}

int translucent(Compiler& c, int n) {
    return c.add_closure(bsdf_node(ClosureKind::Translucent,
                                   {{S::kColor, c.in(n, "Color", 'c', float3(0.8f))},
                                    {S::kNormal, normal_in(c, n)}}));
}

int toon(Compiler& c, int n) {
    ClosureNode node = bsdf_node(ClosureKind::Toon,
                                 {{S::kColor, c.in(n, "Color", 'c', float3(0.8f))},
                                  {S::kNormal, normal_in(c, n)},
                                  {S::kRoughness, c.in(n, "Size", 'f', float3(0.5f))},
                                  {S::kSmooth, c.in(n, "Smooth", 'f')}});
    node.glossy = c.enum_prop(n, "component", "DIFFUSE") == "GLOSSY";
    return c.add_closure(node);
}

int velvet(Compiler& c, int n) {
    return c.add_closure(bsdf_node(ClosureKind::Velvet,
                                   {{S::kColor, c.in(n, "Color", 'c', float3(0.8f))},
                                    {S::kNormal, normal_in(c, n)},
                                    {S::kRoughness, c.in(n, "Sigma", 'f', float3(1))}}));
}

int as_diffuse(Compiler& c, int n) {
    c.unsupported(n, "is drawn as a Diffuse BSDF of its colour");
    const char* color = c.node(n).input("Color") ? "Color" : "Base Color";
    return c.add_closure(bsdf_node(ClosureKind::Diffuse,
                                   {{S::kColor, c.in(n, color, 'c', float3(0.8f))},
                                    {S::kNormal, normal_in(c, n)}}));
}

int emission(Compiler& c, int n) {
    ClosureNode e;
    e.kind = ClosureNode::Kind::Emission;
    e.in[0] = c.in(n, "Color", 'c', float3(1));
    e.in[1] = c.in(n, "Strength", 'f', float3(1));
    return c.add_closure(e);
}

int transparent(Compiler& c, int n) {
    ClosureNode e;
    e.kind = ClosureNode::Kind::Transparent;
    e.in[0] = c.in(n, "Color", 'c', float3(1));
    return c.add_closure(e);
}

// Volume Scatter, Volume Absorption and Principled Volume: read by the volume shader only.
int volume(Compiler& c, int n, ClosureNode::VolumeKind kind) {
    using S = ClosureNode;
    ClosureNode v;
    v.kind = ClosureNode::Kind::Volume;
    v.volume = kind;
    const bool principled = kind == S::VolumeKind::Principled;
    v.in[S::kColor] =
        c.in(n, "Color", 'c', principled ? float3(0.5f) : float3(0.8f));
    v.in[S::kDensity] = c.in(n, "Density", 'f', float3(1));
    if (kind != S::VolumeKind::Absorption) v.in[S::kAnisotropy] = c.in(n, "Anisotropy", 'f', float3(0));
    if (principled) {
        v.in[S::kAbsorptionColor] = c.in(n, "Absorption Color", 'c', float3(0));
        v.in[S::kEmissionStrength] = c.in(n, "Emission Strength", 'f', float3(0));
        v.in[S::kEmission] = c.in(n, "Emission Color", 'c', float3(1));
        v.in[S::kBlackbody] = c.in(n, "Blackbody Intensity", 'f', float3(0));
        v.in[S::kBlackbodyTint] = c.in(n, "Blackbody Tint", 'c', float3(1));
        v.in[S::kTemperature] = c.in(n, "Temperature", 'f', float3(1000));
        // The grids its attribute inputs name (Volume objects), multiplied in where they exist.
        const char* attrs[] = {"Density Attribute", "Color Attribute", "Temperature Attribute"};
        for (int k = 0; k < 3; ++k) {
            const scene::ShaderInput* in = c.node(n).input(attrs[k]);
            if (!in || in->text.empty()) continue;
            if (in->link.linked()) c.unsupported(n, std::string(attrs[k]) + " linked: its own value");
            auto name = std::make_shared<std::string>(in->text);
            v.grids[k] = name.get();
            c.program_keep(name);
            c.reads_volume_grids();
        }
    }
    return c.add_closure(v);
}

int holdout(Compiler& c, int) {
    ClosureNode e;
    e.kind = ClosureNode::Kind::Holdout;
    return c.add_closure(e);
}

int mix_shader(Compiler& c, int n) {
    ClosureNode m;
    m.kind = ClosureNode::Kind::Mix;
    m.fac = c.in(n, "Fac", 'f', float3(0.5f));
    m.a = c.closure(n, "Shader");
    m.b = c.closure(n, "Shader_001");
    return c.add_closure(m);
}

int add_shader(Compiler& c, int n) {
    ClosureNode m;
    m.kind = ClosureNode::Kind::Add;
    m.a = c.closure(n, "Shader");
    m.b = c.closure(n, "Shader_001");
    return c.add_closure(m);
}

// ---------------------------------------------------------------- normals

// Cycles' Bump (svm_node_set_bump): the height at P and at two points a small step away in
// the surface gives its gradient; the normal leans against it by `distance`.
void bump(Compiler& c, int n) {
    const int height = c.in(n, "Height", 'f', float3(1));
    c.set_out(n, "Normal",
              bump_normal(c, height, normal_in(c, n), c.in(n, "Strength", 'f', float3(1)),
                          c.in(n, "Distance", 'f', float3(1)), c.number_prop(n, "invert", 0) != 0));
}

}  // namespace

int bump_normal(Compiler& c, int height, int normal, int strength, int distance, bool invert) {
    const int out = c.fresh();
    Op op;
    op.in[0] = height;
    op.in[1] = normal;
    op.in[2] = strength;
    op.in[3] = distance;
    op.out[0] = out;
    op.i[0] = invert;
    op.sub_end = static_cast<int>(c.mark());
    op.data = &c.program();
    op.fn = [](const Op& o, R r, G sg) {
        const auto* program = static_cast<const ShaderProgram*>(o.data);
        const float h_c = r[o.in[0]].x;
        const float3 normal_in = r[o.in[1]];
        // The height at P + dPdx and P + dPdy, from a copy of the registers.
        thread_local std::vector<float3> scratch;
        const size_t count = program->register_count();
        float h[2];
        for (int k = 0; k < 2; ++k) {
            const float3 d = k == 0 ? sg.dPdx : sg.dPdy;
            ShaderGlobals moved = sg;
            moved.P = sg.P + d;
            float3 od;
            for (int i = 0; i < 3; ++i)
                od[i] = sg.world_to_object[i][0] * d.x + sg.world_to_object[i][1] * d.y +
                        sg.world_to_object[i][2] * d.z;
            moved.object = sg.object + od;
            moved.generated = sg.generated + od * sg.generated_scale;
            // uv moves by the step's components along dPdu and dPdv.
            const float uu = dot(sg.dPdu, sg.dPdu), vv = dot(sg.dPdv, sg.dPdv),
                        uvd = dot(sg.dPdu, sg.dPdv);
            const float det = uu * vv - uvd * uvd;
            if (det > 0) {
                const float a = dot(d, sg.dPdu), b = dot(d, sg.dPdv);
                moved.uv = sg.uv + float3((a * vv - b * uvd) / det, (b * uu - a * uvd) / det, 0);
            }
            scratch.assign(r, r + count);
            program->rerun(static_cast<size_t>(o.sub_end), scratch.data(), moved);
            h[k] = scratch[static_cast<size_t>(o.in[0])].x;
        }
        const float3 dPdx = sg.dPdx, dPdy = sg.dPdy;
        const float3 Rx = cross(dPdy, normal_in), Ry = cross(normal_in, dPdx);
        const float det = dot(dPdx, Rx);
        const float3 surfgrad = Rx * (h[0] - h_c) + Ry * (h[1] - h_c);
        const float absdet = std::fabs(det);
        float strength = std::max(r[o.in[2]].x, 0.0f);
        float distance = r[o.in[3]].x;
        if (o.i[0]) distance = -distance;
        float3 normal_out =
            safe_normalize(normal_in * absdet - surfgrad * (distance * (det < 0 ? -1.0f : 1.0f)));
        normal_out = safe_normalize(normal_out * strength + normal_in * (1.0f - strength));
        r[o.out[0]] = normal_out;
    };
    // A constant height bends nothing.
    if (!c.varying(height)) return normal;
    c.emit(op, false);
    return out;
}

namespace {

// A grid of the volume's object by name at P (`value`), and 1 in `found` where the object has
// it (Cycles' find_attribute: a missing one changes nothing).
void grid_op(Compiler& c, const std::string& name, int value, int found) {
    auto q = std::make_shared<std::string>(name);
    Op op;
    op.data = q.get();
    c.program_keep(q);
    op.out[0] = value;
    op.out[1] = found;
    op.fn = [](const Op& o, R r, G sg) {
        Vec3 v;
        const bool f = sg.grids &&
                       sg.grids->grid(*static_cast<const std::string*>(o.data), sg.P.to_vec3(), &v);
        r[o.out[0]] = f ? float3(v) : float3();
        r[o.out[1]] = float3(f ? 1.0f : 0.0f, 0, 0);
    };
    c.emit(op, false);
}

// Cycles 3.4's Normal Map (svm_node_normal_map). Tangent space works in object space: the
// MikkTSpace tangent and bitangent sign Blender computed for the node's UV map (the mesh's
// Tangent attribute, interpolated over the face unnormalized, as Cycles does) and the normal
// taken back into the object (the face's normal, unflipped, through the transpose), the
// result through the inverse transpose into the world. A mesh without those tangents (none
// exported: an n-gon mesh Blender cannot compute them for) falls back to dPdu, normalized,
// with a positive sign. Blender's own spaces negate Y and Z. A back face flips the result.
void normal_map(Compiler& c, int n) {
    const std::string space = c.enum_prop(n, "space", "TANGENT");
    const int out = c.fresh();
    auto uv_map = std::make_shared<std::string>(c.enum_prop(n, "uv_map", ""));
    Op op;
    op.data = uv_map.get();
    c.program_keep(uv_map);
    op.in[0] = c.in(n, "Color", 'c', float3(0.5f, 0.5f, 1.0f));
    op.in[1] = c.in(n, "Strength", 'f', float3(1));
    op.in[2] = kRegN;
    op.in[3] = kRegUVTangent;
    op.out[0] = out;
    op.i[0] = space == "TANGENT" ? 0 : (space == "OBJECT" || space == "BLENDER_OBJECT") ? 1 : 2;
    op.i[1] = space == "BLENDER_OBJECT" || space == "BLENDER_WORLD";
    op.fn = [](const Op& o, R r, G sg) {
        float3 col = (r[o.in[0]] - float3(0.5f)) * 2.0f;
        const float3 N = r[o.in[2]];
        // v through the inverse transpose of object -> world (an object normal into the
        // world), normalized.
        auto normal_to_world = [&](float3 v) {
            float3 w;
            for (int i = 0; i < 3; ++i)
                w[i] = sg.world_to_object[0][i] * v.x + sg.world_to_object[1][i] * v.y +
                       sg.world_to_object[2][i] * v.z;
            return safe_normalize(w);
        };
        float3 res;
        if (o.i[0] == 0) {
            // The normal as the face has it (N is Ng on a flat face), unflipped.
            const float3 g = sg.backfacing ? -N : N;
            float3 nrm;
            for (int i = 0; i < 3; ++i)
                nrm[i] = sg.object_to_world[0][i] * g.x + sg.object_to_world[1][i] * g.y +
                         sg.object_to_world[2][i] * g.z;
            nrm = safe_normalize(nrm);
            float3 t;
            float sign = 1;
            Vec3 mikk, smooth;
            double mikk_sign = 1;
            const AttributePoint& at = sg.attributes;
            if (at.source && at.source->attribute(*static_cast<const std::string*>(o.data),
                                                  AttributeSource::Want::Tangent, at.face,
                                                  at.b1, at.b2, &mikk, &mikk_sign)) {
                // As Cycles combines them: the tangent and, on a smooth face, the normal as
                // interpolated, not normalized.
                t = float3(mikk);
                sign = static_cast<float>(mikk_sign);
                if (at.source->corner_normal(at.face, at.b1, at.b2, &smooth))
                    nrm = float3(smooth);
            } else {
                const float3 t_world = r[o.in[3]];
                for (int i = 0; i < 3; ++i)
                    t[i] = sg.world_to_object[i][0] * t_world.x +
                           sg.world_to_object[i][1] * t_world.y +
                           sg.world_to_object[i][2] * t_world.z;
                t = safe_normalize(t);
            }
            const float3 B = cross(nrm, t) * sign;
            res = normal_to_world(safe_normalize(t * col.x + B * col.y + nrm * col.z));
        } else {
            if (o.i[1]) col = float3(col.x, -col.y, -col.z);
            res = o.i[0] == 1 ? normal_to_world(col) : safe_normalize(col);
        }
        if (sg.backfacing) res = -res;
        const float strength = r[o.in[1]].x;
        if (strength != 1.0f) res = safe_normalize(N + (res - N) * std::max(strength, 0.0f));
        if (res == float3(0)) res = N;
        r[o.out[0]] = res;
    };
    c.emit(op, false);
    c.set_out(n, "Normal", out);
}

}  // namespace

void add_shader_nodes(NodeTables& t) {
    auto& s = t.shaders;
    s["ShaderNodeBsdfDiffuse"] = diffuse;
    s["ShaderNodeBsdfPrincipled"] = principled;
    s["ShaderNodeBsdfGlossy"] = glossy;
    s["ShaderNodeBsdfAnisotropic"] = glossy;
    s["ShaderNodeBsdfGlass"] = glass;
    s["ShaderNodeBsdfRefraction"] = glass;
    s["ShaderNodeBsdfTranslucent"] = translucent;
    s["ShaderNodeBsdfToon"] = toon;
    s["ShaderNodeBsdfVelvet"] = velvet;
    s["ShaderNodeSubsurfaceScattering"] = subsurface;
    s["ShaderNodeEeveeSpecular"] = as_diffuse;
    s["ShaderNodeEmission"] = emission;
    s["ShaderNodeBackground"] = emission;
    s["ShaderNodeBsdfTransparent"] = transparent;
    s["ShaderNodeHoldout"] = holdout;
    s["ShaderNodeVolumeScatter"] = [](Compiler& c, int n) {
        return volume(c, n, ClosureNode::VolumeKind::Scatter);
    };
    s["ShaderNodeVolumeAbsorption"] = [](Compiler& c, int n) {
        return volume(c, n, ClosureNode::VolumeKind::Absorption);
    };
    s["ShaderNodeVolumePrincipled"] = [](Compiler& c, int n) {
        return volume(c, n, ClosureNode::VolumeKind::Principled);
    };
    s["ShaderNodeMixShader"] = mix_shader;
    s["ShaderNodeAddShader"] = add_shader;
    t.values["ShaderNodeBump"] = bump;
    // Volume Info: the Volume object's standard grids (zero where it has none).
    t.values["ShaderNodeVolumeInfo"] = [](Compiler& c, int n) {
        for (const char* grid : {"Color", "Density", "Flame", "Temperature"}) {
            std::string name = grid;
            name[0] = static_cast<char>(name[0] - 'A' + 'a');
            const int value = c.fresh(), found = c.fresh();
            grid_op(c, name, value, found);
            c.set_out(n, grid, value);
        }
    };
    t.values["ShaderNodeNormalMap"] = normal_map;
}

}  // namespace glint::render::shader
