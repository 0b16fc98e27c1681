// The path tracer's light tree (render/lights/light_tree.h) behind PathLights: emitters of
// many triangles and many small objects keep exact MIS pdfs and an unbiased irradiance
// (against the analytic value), past eight slots POV-Ray and Blender lights join the tree
// without bias (against each light sampled alone), and POV-Ray spots without a radius keep
// their half space.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

#include "render/lights/path_lights.h"
#include "unit/path_test_util.h"

namespace glint::render {
namespace {

using path_test::emitter;

// The emitters' light tree: a mesh of 200 emitting triangles (one tree item, its triangles
// chosen by area times emission) and 150 small separate squares (two triangles each, items of
// their own). From a point just below the squares every sample's pdf is what emitter_pdf()
// gives a BSDF hit at the same point, the near squares are picked far more often than their
// share of the power, and the irradiance estimate matches the analytic value (both emitters
// are rectangles parallel to the receiver).
TEST(PathLights, LightTreeKeepsPdfsExactAndPrefersNearEmitters) {
    scene::Scene s;
    s.materials.push_back(emitter(1));
    s.materials.push_back(emitter(3));
    // The mesh: a 10 x 10 grid of quads (200 triangles) at y = 8, emission 3.
    scene::Mesh grid;
    for (int j = 0; j <= 10; ++j)
        for (int i = 0; i <= 10; ++i) grid.positions.emplace_back(i - 5.0, 8.0, j - 5.0);
    for (int j = 0; j < 10; ++j)
        for (int i = 0; i < 10; ++i) {
            const int a = j * 11 + i;
            grid.faces.push_back({{a, a + 1, a + 12}});
            grid.faces.push_back({{a, a + 12, a + 11}});
        }
    s.meshes.push_back(grid);
    scene::Object mesh_obj;
    mesh_obj.shape = scene::MeshRef{0};
    mesh_obj.material = 1;
    s.objects.push_back(mesh_obj);
    // 150 squares 0.1 x 0.2 at y = 1 side by side: the strip x in [-7.5, 7.5], z in
    // [-0.1, 0.1].
    for (int k = 0; k < 150; ++k) {
        const double x = -7.5 + 0.1 * k;
        scene::Mesh sq;
        sq.positions = {Vec3(x, 1, -0.1), Vec3(x + 0.1, 1, -0.1), Vec3(x + 0.1, 1, 0.1),
                        Vec3(x, 1, 0.1)};
        sq.faces.push_back({{0, 1, 2}});
        sq.faces.push_back({{0, 2, 3}});
        s.meshes.push_back(sq);
        scene::Object o;
        o.shape = scene::MeshRef{static_cast<int>(s.meshes.size()) - 1};
        o.material = 0;
        s.objects.push_back(o);
    }
    PathLights lights(s, {Color(1, 1, 1), Color(3, 3, 3)});
    ASSERT_EQ(lights.count(), 1);
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> U(0, 1);
    const Vec3 p(-3.02, 0.8, 0.01);  // just below the squares near x = -3, facing up
    int near_picks = 0;
    double sum = 0, sum2 = 0;
    const int n = 40000;
    for (int i = 0; i < n; ++i) {
        PathLightSample ls;
        if (!lights.sample(0, p, {U(rng), U(rng)}, &ls)) continue;
        const Vec3 q = p + ls.wi * ls.dist;
        const bool on_mesh = std::fabs(q.y - 8) < 1e-9;
        ASSERT_TRUE(on_mesh || std::fabs(q.y - 1) < 1e-9) << q.y;
        const int object =
            on_mesh ? 0
                    : 1 + std::clamp(static_cast<int>(std::floor((q.x + 7.5) / 0.1)), 0, 149);
        const double pdf = lights.emitter_pdf(object, p, q, Vec3(0, -1, 0),
                                              on_mesh ? Color(3, 3, 3) : Color(1, 1, 1));
        // (A point on the edge two squares share may be taken for either: skip those.)
        const double edge = std::fabs(std::remainder(q.x + 7.5, 0.1));
        if (on_mesh || edge > 1e-9) {
            ASSERT_NEAR(pdf / ls.pdf, 1.0, 1e-6) << "object " << object << " at " << q.x;
        }
        near_picks += !on_mesh && std::fabs(q.x + 3) < 0.5;
        const double e = ls.value.r * ls.wi.y;
        sum += e;
        sum2 += e * e;
    }
    // Irradiance under a rectangle parallel to the receiver at height h, corners relative to
    // the point: the signed sum of its corners' quadrant integrals (radiance 1).
    auto quadrant = [](double x, double z, double h) {
        const double rx = std::sqrt(x * x + h * h), rz = std::sqrt(z * z + h * h);
        return 0.5 * (x / rx * std::atan(z / rx) + z / rz * std::atan(x / rz));
    };
    auto rect = [&](double x0, double x1, double z0, double z1, double h) {
        return quadrant(x1, z1, h) - quadrant(x0, z1, h) - quadrant(x1, z0, h) +
               quadrant(x0, z0, h);
    };
    const double exact = rect(-7.5 - p.x, 7.5 - p.x, -0.1 - p.z, 0.1 - p.z, 1 - p.y) +
                         3 * rect(-5 - p.x, 5 - p.x, -5 - p.z, 5 - p.z, 8 - p.y);
    const double mean = sum / n;
    const double se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
    std::printf("light tree: E = %.5f +- %.2g (analytic %.5f); squares within 0.5 of the "
                "point: %.3f of the picks (%.4f of the power)\n",
                mean, se, exact, static_cast<double>(near_picks) / n, 0.2 / 302.0);
    EXPECT_NEAR(mean, exact, 4 * se);
    EXPECT_GT(near_picks, n * 10 * (0.2 / 302.0));
}

// Past eight slots the lights join the light tree (one slot stands for it): POV-Ray point,
// spot and area lights and Blender point, spot and area lights, scattered over a floor. From
// points on the floor the tree's estimate of the irradiance (one light sample) has the mean
// of the sum of every light's own (each sampled alone), and a parallel light and a Blender
// sun keep slots of their own.
TEST(PathLights, ManyLightsJoinTheTreeAndStayUnbiased) {
    scene::Scene s;
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> U(0, 1);
    for (int i = 0; i < 24; ++i) {
        scene::Light l;
        l.location = Vec3(8 * U(rng) - 4, 0.5 + 2 * U(rng), 8 * U(rng) - 4);
        l.color = Color(0.2 + U(rng), 0.2 + U(rng), 0.2 + U(rng));
        switch (i % 6) {
            case 0: break;  // POV-Ray point light
            case 1:
                l.kind = scene::LightKind::Spot;
                l.point_at = l.location + Vec3(U(rng) - 0.5, -1, U(rng) - 0.5);
                l.radius = 20;
                l.falloff = 35;
                break;
            case 2:
                l.area = scene::AreaLight{Vec3(0.5, 0, 0), Vec3(0, 0, 0.5), 4, 4};
                break;
            default: {
                scene::BlenderLight b;
                b.type = i % 6 == 3   ? scene::BlenderLightType::Point
                         : i % 6 == 4 ? scene::BlenderLightType::Spot
                                      : scene::BlenderLightType::Area;
                b.direction = normalize(Vec3(U(rng) - 0.5, -1, U(rng) - 0.5));
                b.power = 50 + 100 * U(rng);
                b.radius = 0.1;
                b.size_x = b.size_y = 0.4;
                b.axis_x = normalize(cross(b.direction, Vec3(0, 0, 1)));
                b.axis_y = cross(b.axis_x, b.direction);
                l.blender = b;
            }
        }
        s.lights.push_back(l);
    }
    scene::Light parallel;
    parallel.parallel = true;
    parallel.location = Vec3(1, 5, 2);
    parallel.point_at = Vec3(0, 0, 0);
    parallel.color = Color(0.3, 0.3, 0.3);
    s.lights.push_back(parallel);
    const PathLights lights(s, {});
    ASSERT_EQ(lights.count(), 2);  // the tree and the parallel light
    auto irradiance = [](const PathLights& pl, const Vec3& p, std::mt19937_64& r, int n) {
        std::uniform_real_distribution<double> V(0, 1);
        double sum = 0, sum2 = 0;
        for (int i = 0; i < n; ++i) {
            double e = 0;
            for (int k = 0; k < pl.count(); ++k) {
                PathLightSample ls;
                if (pl.sample(k, p, {V(r), V(r)}, &ls) && ls.wi.y > 0)
                    e += (ls.value.r + ls.value.g + ls.value.b) / 3 * ls.wi.y;
            }
            sum += e;
            sum2 += e * e;
        }
        const double mean = sum / n;
        const double se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
        return std::pair<double, double>(mean, se);
    };
    for (const Vec3& p : {Vec3(0.3, 0, -0.2), Vec3(-3, 0, 2.5), Vec3(3.5, 0, 3.5)}) {
        std::mt19937_64 r1(41), r2(42);
        const auto [tree, tree_se] = irradiance(lights, p, r1, 100000);
        // Each light alone, summed.
        double exact = 0, exact_var = 0;
        for (const scene::Light& l : s.lights) {
            scene::Scene one;
            one.lights.push_back(l);
            const PathLights single(one, {});
            const auto [m, se] = irradiance(single, p, r2, l.area || (l.blender &&
                                            l.blender->type != scene::BlenderLightType::Point &&
                                            l.blender->type != scene::BlenderLightType::Spot)
                                                               ? 20000 : 1);
            exact += m;
            exact_var += se * se;
        }
        std::printf("tree of 24 lights at (%g, %g): E = %.5f +- %.2g, each alone %.5f +- %.2g\n",
                    p.x, p.z, tree, tree_se, exact, std::sqrt(exact_var));
        EXPECT_NEAR(tree, exact, 4 * std::sqrt(tree_se * tree_se + exact_var));
    }
}

// POV-Ray spots in the tree are cut off at their falloff only when they have a radius; with
// radius 0 they light the whole half space (their tightness cosine alone), and the tree must
// still pick them for a point far off their axis.
TEST(PathLights, SpotsWithoutARadiusKeepTheirHalfSpaceInTheTree) {
    scene::Scene s;
    for (int i = 0; i < 10; ++i) {
        scene::Light l;
        l.kind = scene::LightKind::Spot;
        l.location = Vec3(i * 0.5, 2, 0);
        l.point_at = l.location - Vec3(0, 1, 0);
        l.radius = 0;
        l.falloff = 10;
        l.color = Color(1, 1, 1);
        s.lights.push_back(l);
    }
    scene::Light bulb;  // a point light right above the point, which the tree favours
    bulb.location = Vec3(30, 3, 0);
    s.lights.push_back(bulb);
    const PathLights lights(s, {});
    ASSERT_EQ(lights.count(), 1);
    const Vec3 p(30, 1.9, 0);  // 88 degrees off every spot's axis, still lit by them
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> U(0, 1);
    int spots = 0;
    for (int i = 0; i < 4000; ++i) {
        PathLightSample ls;
        if (lights.sample(0, p, {U(rng), U(rng)}, &ls) && !ls.value.is_black() && ls.wi.x < 0)
            ++spots;
    }
    EXPECT_GT(spots, 0);
}

}  // namespace
}  // namespace glint::render
