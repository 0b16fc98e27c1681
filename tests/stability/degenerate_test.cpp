// VALIDATION.md case 7: degenerate input (zero-area faces, NaN/Inf/1e30 vertices, an empty
// mesh) is skipped with a warning, nothing crashes, and the image equals the one without it,
// bit for bit, with the Whitted integrator and with the path tracer.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <limits>

#include "stability_support.h"

namespace glint::stability {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

// The scene with degenerate triangles added to its pyramid and an empty mesh object added.
// `huge`: the value of the "1e30" coordinates (the control uses 1e14, which is kept).
scene::Scene with_degenerate_input(scene::Scene s, double huge = 1e30) {
    int mesh_index = -1;
    for (const scene::Object& o : s.objects)
        if (const auto* ref = std::get_if<scene::MeshRef>(&o.shape)) mesh_index = ref->mesh;
    EXPECT_GE(mesh_index, 0);
    if (mesh_index < 0) return s;
    scene::Mesh& m = s.meshes[static_cast<size_t>(mesh_index)];
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const int base = static_cast<int>(m.positions.size());
    m.positions.push_back({nan, 0.5, 0});       // base + 0
    m.positions.push_back({0, inf, 0});         // base + 1
    m.positions.push_back({huge, 0.2, 0.1});    // base + 2
    m.positions.push_back({0.3, huge, -huge});  // base + 3
    m.positions.push_back({0.5, 0.75, -0.5});   // base + 4, on the edge 1-4: collinear
    auto add = [&](int a, int b, int c) {
        scene::MeshFace f;
        f.v = {a, b, c};
        m.faces.push_back(f);
    };
    add(0, 1, 1);         // zero area: repeated vertex
    add(1, base + 4, 4);  // zero area: collinear
    add(0, 1, base + 0);  // NaN
    add(2, base + 1, 3);  // Inf
    add(0, 4, base + 2);  // 1e30
    add(base + 3, 1, 4);  // 1e30 (two coordinates)
    add(base + 2, base + 3, 4);
    s.meshes.emplace_back();  // an empty mesh
    scene::Object empty;
    empty.shape = scene::MeshRef{static_cast<int>(s.meshes.size()) - 1};
    empty.material = s.objects.front().material;
    s.objects.push_back(empty);
    return s;
}

TEST(StabilityDegenerate, Case7SkippedWithWarningAndImageUnchanged) {
    const scene::Scene clean = load_scene("degenerate.pov", "", kWidth, kHeight);
    const scene::Scene dirty = with_degenerate_input(clean);
    for (bool path : {false, true}) {
        render::RenderOptions options;
        options.width = kWidth;
        options.height = kHeight;
        options.threads = 2;
        if (path) {
            options.integrator = render::IntegratorKind::Path;
            options.spp = 4;
            options.seed = 7;
        }
        Diagnostics clean_diag, dirty_diag;
        const render::RenderResult a = render::render(clean, options, clean_diag);
        const render::RenderResult b = render::render(dirty, options, dirty_diag);
        const long n = differing_values(a.image, b.image);
        const int warnings = dirty_diag.warning_count() - clean_diag.warning_count();
        std::printf(
            "case 7 %s: differing film values with degenerate input = %ld of %zu (bound "
            "0); extra warnings = %d (bound >= 1); non-finite = %ld (bound 0)\n",
            path ? "path" : "whitted", n, a.image.rgba.size(), warnings, count_nonfinite(b.image));
        EXPECT_EQ(n, 0) << (path ? "path" : "whitted");
        EXPECT_GE(warnings, 1);
        EXPECT_EQ(count_nonfinite(b.image), 0);
        if (!path) {
            // Not vacuous: with 1e14 instead of 1e30 those triangles are geometry, and show.
            Diagnostics control_diag;
            const render::RenderResult c =
                render::render(with_degenerate_input(clean, 1e14), options, control_diag);
            const long shown = differing_values(a.image, c.image);
            std::printf(
                "case 7 control: the same faces with 1e14 for 1e30 change %ld film "
                "values (bound > 0)\n",
                shown);
            EXPECT_GT(shown, 0);
        }
    }
}

}  // namespace
}  // namespace glint::stability
