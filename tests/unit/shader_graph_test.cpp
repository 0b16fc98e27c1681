// The shader graph compiler and its program (render/shader/program.h): folding, varying
// inputs, the closure tree, transparency, Bump, and what a node glint lacks does.
#include <gtest/gtest.h>

#include <cmath>

#include "render/shader/program.h"
#include "unit/graph_builder.h"

namespace glint::render::shader {
namespace {

using scene::ShaderGraph;
using scene::ShaderInput;
using scene::ShaderNode;
using scene::SocketType;

using G = testing::GraphBuilder;

TEST(ShaderGraph, ConstantMathFoldsToOneEvaluation) {
    G b;
    b.g.name = "folded";
    const int v = b.node("ShaderNodeValue", {{"Value", SocketType::Value}});
    b.g.nodes[v].outputs[0].value[0] = 0.25;
    const int m = b.node("ShaderNodeMath", {{"Value", SocketType::Value}});
    b.prop(m, "operation", "MULTIPLY");
    b.in(m, "Value", SocketType::Value, 0);
    b.in(m, "Value_001", SocketType::Value, 2);
    b.link(m, "Value", v, "Value");
    b.emit(m, "Value");
    Diagnostics diag;
    auto p = ShaderProgram::compile(b.g, nullptr, diag);
    EXPECT_EQ(diag.warning_count(), 0);
    EXPECT_TRUE(p->constant());
    EXPECT_EQ(p->op_count(), 0u);  // everything folded
    ClosureList cl;
    p->evaluate(ShaderGlobals(), &cl);
    EXPECT_DOUBLE_EQ(cl.emission.r, 0.5);  // float to colour: (f, f, f)
    EXPECT_DOUBLE_EQ(cl.emission.b, 0.5);
}

TEST(ShaderGraph, CoordinatesVaryAndConvertAsCycles) {
    G b;
    const int tc = b.node("ShaderNodeTexCoord", {{"Object", SocketType::Vector}});
    const int sep = b.node("ShaderNodeSeparateXYZ", {{"X", SocketType::Value},
                                                      {"Y", SocketType::Value},
                                                      {"Z", SocketType::Value}});
    b.in(sep, "Vector", SocketType::Vector, 0);
    b.link(sep, "Vector", tc, "Object");
    const int m = b.node("ShaderNodeMath", {{"Value", SocketType::Value}});
    b.prop(m, "operation", "ADD");
    b.in(m, "Value", SocketType::Value, 0);
    b.in(m, "Value_001", SocketType::Value, 0);
    b.link(m, "Value", sep, "X");
    b.link(m, "Value_001", sep, "Z");
    b.emit(m, "Value");
    Diagnostics diag;
    auto p = ShaderProgram::compile(b.g, nullptr, diag);
    EXPECT_FALSE(p->constant());
    ShaderGlobals sg;
    sg.object = float3(0.25f, 7.0f, 0.5f);
    ClosureList cl;
    p->evaluate(sg, &cl);
    EXPECT_FLOAT_EQ(static_cast<float>(cl.emission.g), 0.75f);
}

TEST(ShaderGraph, ColourIntoAFloatSocketIsItsLuminance) {
    G b;
    const int rgb = b.node("ShaderNodeRGB", {{"Color", SocketType::Rgba}});
    b.g.nodes[rgb].outputs[0].value[0] = 1;  // pure red
    const int m = b.node("ShaderNodeMath", {{"Value", SocketType::Value}});
    b.prop(m, "operation", "ADD");
    b.in(m, "Value", SocketType::Value, 0);
    b.in(m, "Value_001", SocketType::Value, 0);
    b.link(m, "Value", rgb, "Color");
    b.emit(m, "Value");
    Diagnostics diag;
    auto p = ShaderProgram::compile(b.g, nullptr, diag);
    ClosureList cl;
    p->evaluate(ShaderGlobals(), &cl);
    EXPECT_NEAR(cl.emission.r, 0.2126, 1e-3);  // Rec.709's red weight
}

TEST(ShaderGraph, MixShaderKeepsBothClosuresWeighted) {
    G b;
    const int d = b.node("ShaderNodeBsdfDiffuse", {{"BSDF", SocketType::Shader}});
    b.in(d, "Color", SocketType::Rgba, 1, 0, 0);
    const int gl = b.node("ShaderNodeBsdfGlossy", {{"BSDF", SocketType::Shader}});
    b.in(gl, "Color", SocketType::Rgba, 1, 1, 1);
    b.in(gl, "Roughness", SocketType::Value, 0.3);
    const int mix = b.node("ShaderNodeMixShader", {{"Shader", SocketType::Shader}});
    b.in(mix, "Fac", SocketType::Value, 0.25);
    b.link(mix, "Shader", d, "BSDF");
    b.link(mix, "Shader_001", gl, "BSDF");
    b.link(b.output_node(), "Surface", mix, "Shader");
    Diagnostics diag;
    auto p = ShaderProgram::compile(b.g, nullptr, diag);
    ClosureList cl;
    p->evaluate(ShaderGlobals(), &cl);
    ASSERT_EQ(cl.count(), 2);
    EXPECT_EQ(cl.items[0].kind, ClosureKind::Diffuse);
    EXPECT_DOUBLE_EQ(cl.items[0].weight.r, 0.75);
    EXPECT_EQ(cl.items[1].kind, ClosureKind::Glossy);
    EXPECT_DOUBLE_EQ(cl.items[1].weight.r, 0.25);
    EXPECT_NEAR(cl.items[1].roughness, 0.3, 1e-6);
}

TEST(ShaderGraph, PrincipledAlphaBecomesTransparency) {
    G b;
    const int pr = b.node("ShaderNodeBsdfPrincipled", {{"BSDF", SocketType::Shader}});
    b.in(pr, "Base Color", SocketType::Rgba, 0.8, 0.8, 0.8);
    b.in(pr, "Alpha", SocketType::Value, 0.4);
    b.link(b.output_node(), "Surface", pr, "BSDF");
    Diagnostics diag;
    auto p = ShaderProgram::compile(b.g, nullptr, diag);
    ClosureList cl;
    p->evaluate(ShaderGlobals(), &cl);
    ASSERT_EQ(cl.count(), 1);
    EXPECT_NEAR(cl.items[0].weight.g, 0.4, 1e-6);
    EXPECT_NEAR(cl.transparent.g, 0.6, 1e-6);
}

// Whether shadow rays may pass a surface is read off the graph once: only graphs that can make
// a transparent closure send shadow rays through the slower walk that evaluates them.
TEST(ShaderGraph, TransparencyIsKnownFromTheGraph) {
    auto compile = [](G& b) {
        Diagnostics diag;
        return ShaderProgram::compile(b.g, nullptr, diag);
    };
    {  // A plain Diffuse BSDF (its normal varies): opaque.
        G b;
        const int d = b.node("ShaderNodeBsdfDiffuse", {{"BSDF", SocketType::Shader}});
        b.in(d, "Color", SocketType::Rgba, 0.5, 0.5, 0.5);
        b.link(b.output_node(), "Surface", d, "BSDF");
        auto p = compile(b);
        EXPECT_FALSE(p->constant());
        EXPECT_FALSE(p->can_be_transparent());
    }
    {  // Principled with Alpha 1: opaque; below 1: transparent.
        for (double alpha : {1.0, 0.999}) {
            G b;
            const int pr = b.node("ShaderNodeBsdfPrincipled", {{"BSDF", SocketType::Shader}});
            b.in(pr, "Alpha", SocketType::Value, alpha);
            b.link(b.output_node(), "Surface", pr, "BSDF");
            EXPECT_EQ(compile(b)->can_be_transparent(), alpha < 1) << alpha;
        }
    }
    {  // Alpha from a texture coordinate (varies): may be transparent.
        G b;
        const int tc = b.node("ShaderNodeTexCoord", {{"Generated", SocketType::Vector}});
        const int pr = b.node("ShaderNodeBsdfPrincipled", {{"BSDF", SocketType::Shader}});
        b.link(pr, "Alpha", tc, "Generated");
        b.link(b.output_node(), "Surface", pr, "BSDF");
        EXPECT_TRUE(compile(b)->can_be_transparent());
    }
    {  // A Transparent BSDF mixed in, however little; a black one lets nothing through.
        for (double c : {1.0, 0.0}) {
            G b;
            const int d = b.node("ShaderNodeBsdfDiffuse", {{"BSDF", SocketType::Shader}});
            const int t = b.node("ShaderNodeBsdfTransparent", {{"BSDF", SocketType::Shader}});
            b.in(t, "Color", SocketType::Rgba, c, c, c);
            const int mix = b.node("ShaderNodeMixShader", {{"Shader", SocketType::Shader}});
            b.in(mix, "Fac", SocketType::Value, 0.01);
            b.link(mix, "Shader", d, "BSDF");
            b.link(mix, "Shader_001", t, "BSDF");
            b.link(b.output_node(), "Surface", mix, "Shader");
            auto p = compile(b);
            EXPECT_EQ(p->can_be_transparent(), c > 0) << c;
            ClosureList cl;
            p->evaluate(ShaderGlobals(), &cl);
            EXPECT_EQ(cl.transparent.is_black(), !p->can_be_transparent());
        }
    }
}

// Graphs whose closures vary only by the shading normal are evaluated once: the path tracer
// copies those closures and gives the ones that read N the point's normal. That must equal a
// full evaluation, and only such graphs may be marked.
TEST(ShaderGraph, NormalOnlyGraphsAreMarkedAndTheirClosuresReadN) {
    auto principled = [](double anisotropic, bool textured) {
        G b;
        const int pr = b.node("ShaderNodeBsdfPrincipled", {{"BSDF", SocketType::Shader}});
        b.in(pr, "Base Color", SocketType::Rgba, 0.8, 0.5, 0.2);
        b.in(pr, "Roughness", SocketType::Value, 0.4);
        b.in(pr, "Clearcoat", SocketType::Value, 0.5);
        b.in(pr, "Anisotropic", SocketType::Value, anisotropic);
        if (textured) {
            const int tc = b.node("ShaderNodeTexCoord", {{"Generated", SocketType::Vector}});
            b.link(pr, "Base Color", tc, "Generated");
        }
        b.link(b.output_node(), "Surface", pr, "BSDF");
        Diagnostics diag;
        return ShaderProgram::compile(b.g, nullptr, diag);
    };
    auto plain = principled(0, false);
    EXPECT_FALSE(plain->constant());
    ASSERT_TRUE(plain->normal_only());
    // Evaluated at two normals, the closures differ in their normals alone, which are N.
    ShaderGlobals up, tilted;
    up.N = float3(0, 0, 1);
    tilted.N = float3(0.6f, 0, 0.8f);
    tilted.tangent = float3(0, 1, 0);
    ClosureList a, c;
    plain->evaluate(up, &a);
    plain->evaluate(tilted, &c);
    ASSERT_EQ(a.count(), 1);
    ASSERT_EQ(c.count(), 1);
    EXPECT_TRUE(c.items[0].n_from_globals);
    EXPECT_TRUE(c.items[0].clearcoat_n_from_globals);
    EXPECT_EQ(c.items[0].N, tilted.N.to_vec3());
    EXPECT_EQ(c.items[0].clearcoat_N, tilted.N.to_vec3());
    EXPECT_EQ(c.N, tilted.N.to_vec3());
    EXPECT_EQ(a.items[0].weight, c.items[0].weight);
    EXPECT_EQ(a.items[0].color, c.items[0].color);
    EXPECT_EQ(a.items[0].T, c.items[0].T);  // no anisotropy: the tangent is not read
    // Anisotropy reads the tangent, a texture varies the colour: not marked.
    EXPECT_FALSE(principled(0.5, false)->normal_only());
    EXPECT_FALSE(principled(0, true)->normal_only());
    // A linked Normal (a Normal Map, a Bump) is not N: not marked.
    G b;
    const int d = b.node("ShaderNodeBsdfDiffuse", {{"BSDF", SocketType::Shader}});
    const int tc = b.node("ShaderNodeTexCoord", {{"Normal", SocketType::Vector}});
    b.link(d, "Normal", tc, "Normal");
    b.link(b.output_node(), "Surface", d, "BSDF");
    Diagnostics diag;
    EXPECT_FALSE(ShaderProgram::compile(b.g, nullptr, diag)->normal_only());
}

TEST(ShaderGraph, BumpLeansAgainstTheHeightGradient) {
    G b;
    const int tc = b.node("ShaderNodeTexCoord", {{"Object", SocketType::Vector}});
    const int sep = b.node("ShaderNodeSeparateXYZ", {{"X", SocketType::Value}});
    b.in(sep, "Vector", SocketType::Vector, 0);
    b.link(sep, "Vector", tc, "Object");
    const int bump = b.node("ShaderNodeBump", {{"Normal", SocketType::Vector}});
    b.in(bump, "Strength", SocketType::Value, 1);
    b.in(bump, "Distance", SocketType::Value, 1);
    b.in(bump, "Height", SocketType::Value, 0);
    b.link(bump, "Height", sep, "X");
    const int d = b.node("ShaderNodeBsdfDiffuse", {{"BSDF", SocketType::Shader}});
    b.in(d, "Color", SocketType::Rgba, 1, 1, 1);
    b.in(d, "Normal", SocketType::Vector, 0);
    b.link(d, "Normal", bump, "Normal");
    b.link(b.output_node(), "Surface", d, "BSDF");
    Diagnostics diag;
    auto p = ShaderProgram::compile(b.g, nullptr, diag);
    ShaderGlobals sg;
    sg.N = sg.Ng = float3(0, 0, 1);
    sg.dPdx = float3(1e-3f, 0, 0);
    sg.dPdy = float3(0, 1e-3f, 0);
    ClosureList cl;
    p->evaluate(sg, &cl);
    ASSERT_EQ(cl.count(), 1);
    // Height x, distance 1: the normal (-1, 0, 1) / sqrt(2).
    EXPECT_NEAR(cl.items[0].N.x, -std::sqrt(0.5), 1e-3);
    EXPECT_NEAR(cl.items[0].N.z, std::sqrt(0.5), 1e-3);
}

TEST(ShaderGraph, AMissingNodeIsOneWarningNamingItNeverACrash) {
    G b;
    b.g.name = "Rusty";
    const int x = b.node("ShaderNodeTexPointDensity", {{"Color", SocketType::Rgba}});
    b.g.nodes[x].name = "Point Density";
    const int d = b.node("ShaderNodeBsdfDiffuse", {{"BSDF", SocketType::Shader}});
    b.in(d, "Color", SocketType::Rgba, 0.5, 0.5, 0.5);
    b.link(d, "Color", x, "Color");
    const int d2 = b.node("ShaderNodeBsdfDiffuse", {{"BSDF", SocketType::Shader}});
    b.in(d2, "Color", SocketType::Rgba, 0.5, 0.5, 0.5);
    b.link(d2, "Color", x, "Color");
    const int add = b.node("ShaderNodeAddShader", {{"Shader", SocketType::Shader}});
    b.link(add, "Shader", d, "BSDF");
    b.link(add, "Shader_001", d2, "BSDF");
    b.link(b.output_node(), "Surface", add, "Shader");
    Diagnostics diag;
    auto p = ShaderProgram::compile(b.g, nullptr, diag);
    ASSERT_EQ(diag.warning_count(), 1);
    EXPECT_NE(diag.all()[0].message.find("Point Density"), std::string::npos);
    EXPECT_NE(diag.all()[0].message.find("Rusty"), std::string::npos);
    ClosureList cl;
    p->evaluate(ShaderGlobals(), &cl);
    EXPECT_EQ(cl.count(), 0);  // black colour: no closure worth sampling
}

TEST(ShaderGraph, ALinkCycleIsCutWithAWarning) {
    G b;
    const int m1 = b.node("ShaderNodeMath", {{"Value", SocketType::Value}});
    const int m2 = b.node("ShaderNodeMath", {{"Value", SocketType::Value}});
    for (int m : {m1, m2}) {
        b.prop(m, "operation", "ADD");
        b.in(m, "Value", SocketType::Value, 0.5);
        b.in(m, "Value_001", SocketType::Value, 0.5);
    }
    b.link(m1, "Value", m2, "Value");
    b.link(m2, "Value", m1, "Value");
    b.emit(m1, "Value");
    Diagnostics diag;
    auto p = ShaderProgram::compile(b.g, nullptr, diag);
    EXPECT_GE(diag.warning_count(), 1);
    ClosureList cl;
    p->evaluate(ShaderGlobals(), &cl);
    EXPECT_TRUE(std::isfinite(cl.emission.r));
}


// Cycles 3.4's volume closures (svm_node_principled_volume, svm_node_closure_volume): the
// coefficients the path tracer's media take from a material's Volume output.
TEST(ShaderGraph, VolumeShadersGiveCyclesCoefficients) {
    G b;
    const int pv = b.node("ShaderNodeVolumePrincipled", {{"Volume", SocketType::Shader}});
    b.in(pv, "Color", SocketType::Rgba, 0.8, 0.5, 0.2);
    b.in(pv, "Density", SocketType::Value, 2);
    b.in(pv, "Anisotropy", SocketType::Value, 0.3);
    b.in(pv, "Absorption Color", SocketType::Rgba, 0.25, 0, 1);
    b.in(pv, "Emission Strength", SocketType::Value, 0.5);
    b.in(pv, "Emission Color", SocketType::Rgba, 1, 0.5, 0);
    const int ab = b.node("ShaderNodeVolumeAbsorption", {{"Volume", SocketType::Shader}});
    b.in(ab, "Color", SocketType::Rgba, 0.25, 0.5, 1);
    b.in(ab, "Density", SocketType::Value, 4);
    const int mix = b.node("ShaderNodeMixShader", {{"Shader", SocketType::Shader}});
    b.in(mix, "Fac", SocketType::Value, 0.25);
    b.link(mix, "Shader", pv, "Volume");
    b.link(mix, "Shader_001", ab, "Volume");
    b.link(b.output_node(), "Volume", mix, "Shader");
    Diagnostics diag;
    auto p = ShaderProgram::compile(b.g, nullptr, diag);
    EXPECT_EQ(diag.warning_count(), 0);
    ASSERT_TRUE(p->has_volume());
    EXPECT_FALSE(p->has_surface());
    EXPECT_TRUE(p->volume_constant());
    VolumeClosures v;
    p->evaluate_volume(ShaderGlobals(), &v);
    // Principled at mix weight 0.75: density 1.5, sigma_s = colour * density, extinction
    // (colour + (1 - colour)(1 - sqrt(absorption colour))) * density; the absorption at 0.25:
    // (1 - colour) * 4 * 0.25. Emission is not scaled by density or mix.
    ASSERT_EQ(v.count, 1);
    EXPECT_NEAR(v.lobes[0].sigma_s.r, 0.8 * 1.5, 1e-6);
    EXPECT_NEAR(v.lobes[0].g, 0.3, 1e-6);
    EXPECT_NEAR(v.extinction.r, (0.8 + 0.2 * 0.5) * 1.5 + 0.75, 1e-6);
    EXPECT_NEAR(v.extinction.g, (0.5 + 0.5 * 1.0) * 1.5 + 0.5, 1e-6);
    EXPECT_NEAR(v.extinction.b, (0.2 + 0.8 * 0.0) * 1.5 + 0.0, 1e-6);
    EXPECT_NEAR(v.emission.r, 0.5, 1e-6);
    EXPECT_NEAR(v.emission.g, 0.25, 1e-6);
    // Without a surface the boundary lets rays through.
    ClosureList cl;
    p->evaluate(ShaderGlobals(), &cl);
    EXPECT_EQ(cl.count(), 0);
    EXPECT_EQ(cl.transparent, Color(1, 1, 1));
}

TEST(ShaderGraph, VaryingVolumeIsFlagged) {
    G b;
    const int tc = b.node("ShaderNodeTexCoord", {{"Object", SocketType::Vector}});
    const int sep = b.node("ShaderNodeSeparateXYZ", {{"X", SocketType::Value}});
    b.in(sep, "Vector", SocketType::Vector, 0);
    b.link(sep, "Vector", tc, "Object");
    const int sc = b.node("ShaderNodeVolumeScatter", {{"Volume", SocketType::Shader}});
    b.in(sc, "Color", SocketType::Rgba, 1, 1, 1);
    b.in(sc, "Density", SocketType::Value, 1);
    b.link(sc, "Density", sep, "X");
    b.link(b.output_node(), "Volume", sc, "Volume");
    Diagnostics diag;
    auto p = ShaderProgram::compile(b.g, nullptr, diag);
    EXPECT_FALSE(p->volume_constant());
    EXPECT_EQ(diag.warning_count(), 0);  // ray marched, in objects and in the world
}

}  // namespace
}  // namespace glint::render::shader
