// The path tracer's view of node-graph materials (render/prepare/material_table.h): which
// emit a constant radiance (then light sampling picks their objects, as Cycles samples every
// emitting mesh) and which may let shadow rays through.
#include <gtest/gtest.h>

#include "render/prepare/prepared_scene.h"
#include "unit/graph_builder.h"

namespace glint::render {
namespace {

using scene::SocketType;
using G = testing::GraphBuilder;

// A scene of one material per graph, prepared for the path tracer.
std::unique_ptr<PreparedScene> prepared(const std::vector<scene::ShaderGraph>& graphs,
                                        scene::Scene* s) {
    for (size_t i = 0; i < graphs.size(); ++i) {
        s->shader_graphs.push_back(graphs[i]);
        scene::Material m;
        m.graph = static_cast<int>(i);
        s->materials.push_back(m);
    }
    RenderOptions options;
    options.integrator = IntegratorKind::Path;
    options.width = options.height = 8;
    Diagnostics diag;
    return prepare(*s, options, diag);
}

TEST(GraphMaterial, PrincipledEmissionIsLightSampledAndOpaque) {
    G emitter;  // a Principled BSDF with Emission: its normal varies, its emission does not
    const int pr = emitter.node("ShaderNodeBsdfPrincipled", {{"BSDF", SocketType::Shader}});
    emitter.in(pr, "Base Color", SocketType::Rgba, 0.1, 0.1, 0.1);
    emitter.in(pr, "Emission", SocketType::Rgba, 1.0, 0.5, 0.2);
    emitter.in(pr, "Emission Strength", SocketType::Value, 3.0);
    emitter.link(emitter.output_node(), "Surface", pr, "BSDF");
    G textured;  // emission from a texture coordinate: not constant, so not light-sampled
    const int pt = textured.node("ShaderNodeBsdfPrincipled", {{"BSDF", SocketType::Shader}});
    const int tc = textured.node("ShaderNodeTexCoord", {{"Generated", SocketType::Vector}});
    textured.link(pt, "Emission", tc, "Generated");
    textured.link(textured.output_node(), "Surface", pt, "BSDF");
    G see_through;  // a Transparent BSDF mixed in: shadow rays must look at it
    const int d = see_through.node("ShaderNodeBsdfDiffuse", {{"BSDF", SocketType::Shader}});
    const int t = see_through.node("ShaderNodeBsdfTransparent", {{"BSDF", SocketType::Shader}});
    see_through.in(t, "Color", SocketType::Rgba, 1, 1, 1);
    const int mix = see_through.node("ShaderNodeMixShader", {{"Shader", SocketType::Shader}});
    see_through.in(mix, "Fac", SocketType::Value, 0.5);
    see_through.link(mix, "Shader", d, "BSDF");
    see_through.link(mix, "Shader_001", t, "BSDF");
    see_through.link(see_through.output_node(), "Surface", mix, "Shader");

    scene::Scene s;
    auto p = prepared({emitter.g, textured.g, see_through.g}, &s);
    const PathMaterial* e = p->materials.path(0);
    ASSERT_NE(e, nullptr);
    EXPECT_NEAR(e->emission.r, 3.0, 1e-6);
    EXPECT_NEAR(e->emission.g, 1.5, 1e-6);
    EXPECT_NEAR(e->emission.b, 0.6, 1e-6);
    EXPECT_FALSE(e->has_alpha);
    EXPECT_TRUE(e->normal_closures != nullptr);
    EXPECT_TRUE(p->materials.path(1)->emission.is_black());
    EXPECT_TRUE(p->materials.path(2)->has_alpha);
    EXPECT_TRUE(p->materials.any_alpha());
}

}  // namespace
}  // namespace glint::render
