// POV-Ray's quadric, polygon, prism, lathe, sor, superellipsoid, blob, height_field and poly:
// hits, normals and inside tests against closed forms, and the importer's messages for misuse.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>
#include <random>

#include "geom_test_util.h"
#include "pov_test_util.h"
#include "render/shapes/object_node.h"
#include "render/shapes/polynomial/blob.h"
#include "render/shapes/shapes.h"

namespace glint {
namespace {

using render::Hit;
using test::build_one;
using test::ray;
using test::inside;

void expect_vec(const Vec3& a, const Vec3& b, double tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// ---- quadric -----------------------------------------------------------------------------

TEST(Quadric, SphereAndParaboloid) {
    scene::Quadric q;  // x^2 + y^2 + z^2 - 1
    auto g = build_one(q);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 4, 1e-12);
    expect_vec(h.ng, {0, 0, -1}, 1e-12);
    EXPECT_TRUE(inside(q, {0.5, 0, 0}));
    EXPECT_FALSE(inside(q, {1.5, 0, 0}));
    EXPECT_NEAR(g->bounds().hi.x, 1, 1e-5);  // an ellipsoid is bounded
    // y = x^2 + z^2 (paraboloid): x^2 + z^2 - y = 0, unbounded.
    scene::Quadric p{{1, 0, 1}, {0, 0, 0}, {0, -1, 0}, 0};
    auto gp = build_one(p);
    ASSERT_TRUE(gp->intersect(ray({1, 5, 0}, {0, -1, 0}), &h));
    EXPECT_NEAR(h.t, 4, 1e-12);  // hits at y = 1
    expect_vec(h.ng, normalize(Vec3(2, -1, 0)), 1e-12);
    EXPECT_TRUE(gp->bounds().is_infinite());
}

// ---- polygon -----------------------------------------------------------------------------

TEST(Polygon, SquareWithHole) {
    // Outer square and an inner square hole (second sub-polygon), in the plane z = 1.
    scene::Polygon s{{{0, 0, 1}, {4, 0, 1}, {4, 4, 1}, {0, 4, 1}, {0, 0, 1},
                      {1, 1, 1}, {3, 1, 1}, {3, 3, 1}, {1, 3, 1}, {1, 1, 1}}};
    auto g = build_one(s);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0.5, 0.5, -2}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 3, 1e-12);
    EXPECT_NEAR(std::fabs(h.ng.z), 1, 1e-12);
    EXPECT_FALSE(g->intersect(ray({2, 2, -2}, {0, 0, 1}), &h));  // in the hole
    EXPECT_FALSE(inside(s, {0.5, 0.5, 1}));                       // no inside
}

// ---- prism -------------------------------------------------------------------------------

scene::Prism square_prism(bool conic) {
    scene::Prism p;
    p.conic = conic;
    p.height1 = conic ? 0.5 : 0;
    p.height2 = 1;
    p.points = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
    return p;
}

TEST(Prism, LinearSweepSidesCapsInside) {
    auto p = square_prism(false);
    auto g = build_one(p);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({-5, 0.5, 0}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 4, 1e-12);
    expect_vec(h.ng, {-1, 0, 0}, 1e-12);  // outward
    ASSERT_TRUE(g->intersect(ray({0.2, 5, 0.3}, {0, -1, 0}), &h));
    EXPECT_NEAR(h.t, 4, 1e-12);
    expect_vec(h.ng, {0, 1, 0}, 1e-12);
    EXPECT_EQ(test::hit_depths(p, ray({-5, 0.5, 0}, {1, 0, 0})).size(), 2u);
    EXPECT_TRUE(inside(p, {0, 0.5, 0}));
    EXPECT_FALSE(inside(p, {0, 1.5, 0}));
    EXPECT_FALSE(inside(p, {1.5, 0.5, 0}));
    p.open = true;
    g = build_one(p);
    EXPECT_FALSE(g->intersect(ray({0.2, 5, 0.3}, {0, -1, 0}), &h));
}

TEST(Prism, ConicSweepScalesWithHeight) {
    auto p = square_prism(true);
    auto g = build_one(p);
    Hit h;
    // At y = 0.75 the outline is the square of half-width 0.75.
    ASSERT_TRUE(g->intersect(ray({-5, 0.75, 0}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 5 - 0.75, 1e-12);
    EXPECT_LT(h.ng.x, 0);
    EXPECT_TRUE(inside(p, {0.6, 0.75, 0}));
    EXPECT_FALSE(inside(p, {0.8, 0.75, 0}));
}

TEST(Prism, CubicSplineIsSmoothAndClosed) {
    scene::Prism p;
    p.spline = scene::SplineType::Cubic;
    // A Catmull-Rom loop through the square's corners (first/last points are controls).
    p.points = {{-1, 1}, {-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    auto g = build_one(p);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 0.5, -5}, {0, 0, 1}), &h));
    // The curve bulges past the corners' square between them.
    EXPECT_LT(h.t, 4);
    EXPECT_TRUE(inside(p, {0, 0.5, 0}));
}

// ---- lathe and sor -----------------------------------------------------------------------

TEST(Lathe, LinearProfileIsACylinder) {
    scene::Lathe l;
    l.points = {{0, 0}, {1, 0}, {1, 2}, {0, 2}};
    auto g = build_one(l);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({-5, 1, 0}, {1, 0, 0}), &h));  // horizontal ray
    EXPECT_NEAR(h.t, 4, 1e-9);
    expect_vec(h.ng, {-1, 0, 0}, 1e-9);
    ASSERT_TRUE(g->intersect(ray({-5, 2.5, 0}, {5, -1, 0}), &h));  // slanted into the side
    EXPECT_NEAR(h.p.x, -1, 1e-9);
    ASSERT_TRUE(g->intersect(ray({0.5, 5, 0}, {0, -1, 0}), &h));  // the top disc
    EXPECT_NEAR(h.t, 3, 1e-9);
    expect_vec(h.ng, {0, 1, 0}, 1e-9);
    EXPECT_TRUE(inside(l, {0.5, 1, 0.2}));
    EXPECT_FALSE(inside(l, {1.5, 1, 0}));
}

TEST(Lathe, QuadraticAndBezier) {
    scene::Lathe q;
    q.spline = scene::SplineType::Quadratic;
    q.points = {{1, -1}, {1, 0}, {1, 1}, {1, 2}};  // straight radius 1 between y 0 and 1
    auto g = build_one(q);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({-5, 0.5, 0}, {1, 0.01, 0}), &h));
    EXPECT_NEAR(h.p.x, -1, 1e-9);
    scene::Lathe b;
    b.spline = scene::SplineType::Bezier;
    b.points = {{1, 0}, {1, 1}, {1, 2}, {1, 3}};
    g = build_one(b);
    ASSERT_TRUE(g->intersect(ray({0, 1.5, 5}, {0, 0, -1}), &h));
    EXPECT_NEAR(h.t, 4, 1e-9);
}

TEST(Lathe, UvIsTheTurnAndTheSplineParameter) {
    // Lathe::UVCoord: u the turn about y from +x towards +z, v (segment + parameter) over
    // the segment count. Linear profile: three segments (the bottom disc, the wall, the top).
    scene::Lathe l;
    l.points = {{0, 0}, {1, 0}, {1, 2}, {0, 2}};
    auto g = build_one(l);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 1.5, -5}, {0, 0, 1}), &h));  // the wall at -z
    ASSERT_TRUE(h.has_uv);
    EXPECT_NEAR(h.uv.x, 0.75, 1e-12);
    EXPECT_NEAR(h.uv.y, (1 + 0.75) / 3, 1e-9);
    ASSERT_TRUE(g->intersect(ray({-0.5, 5, 0}, {0, -1, 0}), &h));  // the top disc at -x
    EXPECT_NEAR(h.uv.x, 0.5, 1e-12);
    EXPECT_NEAR(h.uv.y, (2 + 0.5) / 3, 1e-9);
}

TEST(Sor, UvUpTheCurveAcrossBaseAndCap) {
    // Sor::UVCoord: v 0..1 up the curve, -1..0 across the base, 1..2 across the cap.
    scene::Sor s;
    s.points = {{1, -1}, {1, 0}, {1, 1}, {1, 2}};  // one segment, y 0..1, radius 1
    auto g = build_one(s);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({5, 0.25, 0}, {-1, 0, 0}), &h));  // the wall at +x
    ASSERT_TRUE(h.has_uv);
    EXPECT_NEAR(h.uv.x, 0, 1e-12);
    EXPECT_NEAR(h.uv.y, 0.25, 1e-9);
    ASSERT_TRUE(g->intersect(ray({0, 5, 0.5}, {0, -1, 0}), &h));  // the cap, half way out
    EXPECT_NEAR(h.uv.x, 0.25, 1e-12);
    EXPECT_NEAR(h.uv.y, 1.5, 1e-9);
    ASSERT_TRUE(g->intersect(ray({0, -5, -0.25}, {0, 1, 0}), &h));  // the base
    EXPECT_NEAR(h.uv.x, 0.75, 1e-12);
    EXPECT_NEAR(h.uv.y, -0.75, 1e-9);
}

TEST(Sor, CylinderWithCaps) {
    scene::Sor s;
    s.points = {{1, -1}, {1, 0}, {1, 1}, {1, 2}};
    auto g = build_one(s);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({-5, 0.5, 0}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 4, 1e-12);
    expect_vec(h.ng, {-1, 0, 0}, 1e-12);
    ASSERT_TRUE(g->intersect(ray({0.3, 5, 0}, {0, -1, 0}), &h));
    EXPECT_NEAR(h.t, 4, 1e-12);  // cap at y = 1
    EXPECT_TRUE(inside(s, {0.5, 0.5, 0}));
    EXPECT_FALSE(inside(s, {0.5, 1.5, 0}));
    s.open = true;
    g = build_one(s);
    EXPECT_FALSE(g->intersect(ray({0.3, 5, 0}, {0, -1, 0}), &h));  // along the open tube
}

// ---- superellipsoid ----------------------------------------------------------------------

TEST(Superellipsoid, SphereAndRoundedBox) {
    scene::Superellipsoid s{1, 1};  // the unit sphere
    auto g = build_one(s);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0.3, 0.2, -5}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 5 - std::sqrt(1 - 0.13), 1e-9);
    expect_vec(h.ng, normalize(h.p), 1e-6);
    EXPECT_TRUE(inside(s, {0.5, 0.5, 0.5}));
    EXPECT_FALSE(inside(s, {0.75, 0.75, 0}));
    scene::Superellipsoid box{0.1, 0.1};  // nearly a cube: its corner region is inside
    EXPECT_TRUE(inside(box, {0.9, 0.9, 0.9}));
    g = build_one(box);
    ASSERT_TRUE(g->intersect(ray({0.5, 0.5, -5}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 4, 1e-6);
    expect_vec(h.ng, {0, 0, -1}, 1e-4);
}

// ---- blob --------------------------------------------------------------------------------

TEST(Blob, SphereAndCylinderComponents) {
    // One sphere: (1 - r^2/4)^2 = 0.5 at r = 2 sqrt(1 - sqrt(0.5)).
    scene::Blob b;
    b.threshold = 0.5;
    scene::BlobComponent c;
    c.radius = 2;
    c.strength = 1;
    b.components.push_back(c);
    const double r = 2 * std::sqrt(1 - std::sqrt(0.5));
    auto g = build_one(b);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 5 - r, 1e-9);
    expect_vec(h.ng, {0, 0, -1}, 1e-9);
    EXPECT_TRUE(inside(b, {0, 0, 0}));
    EXPECT_FALSE(inside(b, {0, 0, r + 0.01}));
    // A cylinder component: the same radius around its axis, hemispherical ends.
    scene::Blob cyl = b;
    cyl.components[0].cylinder = true;
    cyl.components[0].center = {0, -1, 0};
    cyl.components[0].apex = {0, 1, 0};
    g = build_one(cyl);
    ASSERT_TRUE(g->intersect(ray({-5, 0.3, 0}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 5 - r, 1e-9);
    ASSERT_TRUE(g->intersect(ray({0, 5, 0}, {0, -1, 0}), &h));
    EXPECT_NEAR(h.t, 4 - r, 1e-9);
    // Two overlapping spheres merge: the midpoint between them is inside.
    scene::Blob two = b;
    two.threshold = 0.6;
    two.components[0].center = {-1, 0, 0};
    two.components.push_back(two.components[0]);
    two.components[1].center = {1, 0, 0};
    EXPECT_TRUE(inside(two, {0, 0, 0}));
    EXPECT_EQ(test::hit_depths(two, ray({-5, 0, 0}, {1, 0, 0})).size(), 2u);
}

TEST(Blob, ComponentTexturesBlendByField) {
    // Two spheres at x = -1 (material 1) and x = 1 (material 2), influence radius 1.5.
    scene::Blob b;
    b.threshold = 0.3;
    scene::BlobComponent c;
    c.radius = 1.5;
    c.center = {-1, 0, 0};
    c.material = 1;
    b.components.push_back(c);
    c.center = {1, 0, 0};
    c.material = 2;
    b.components.push_back(c);
    auto g = build_one(b);
    Hit h;
    std::vector<render::TextureWeight> w;
    // At x = -1.5 only the first component's field reaches: its texture alone.
    ASSERT_TRUE(g->intersect(ray({-1.5, 0, -5}, {0, 0, 1}), &h));
    ASSERT_NE(h.blend_source, nullptr);
    ASSERT_TRUE(h.blend_source->texture_blend(h.blend_point, &w));
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].material, 1);
    EXPECT_DOUBLE_EQ(w[0].weight, 1.0);
    // Halfway between them: both, half each.
    ASSERT_TRUE(g->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
    ASSERT_TRUE(h.blend_source->texture_blend(h.blend_point, &w));
    ASSERT_EQ(w.size(), 2u);
    EXPECT_NEAR(w[0].weight, 0.5, 1e-9);
    EXPECT_NEAR(w[1].weight, 0.5, 1e-9);
    EXPECT_NE(w[0].material, w[1].material);
    // Nearer the second one (x = 0.2, where both fields still reach): its weight is the
    // larger, by the ratio of the fields.
    ASSERT_TRUE(g->intersect(ray({0.2, 0, -5}, {0, 0, 1}), &h));
    ASSERT_TRUE(h.blend_source->texture_blend(h.blend_point, &w));
    ASSERT_EQ(w.size(), 2u);
    const double w2 = w[0].material == 2 ? w[0].weight : w[1].weight;
    const Vec3 p = h.blend_point;
    auto field = [&](double cx) {
        double r2 = (p.x - cx) * (p.x - cx) + p.y * p.y + p.z * p.z;
        return (1 - r2 / 2.25) * (1 - r2 / 2.25);
    };
    EXPECT_NEAR(w2, field(1) / (field(1) + field(-1)), 1e-9);
    EXPECT_GT(w2, 0.5);
    // Without component textures the blob names no blend.
    b.components[0].material = b.components[1].material = -1;
    g = build_one(b);
    ASSERT_TRUE(g->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
    EXPECT_EQ(h.blend_source, nullptr);
}

TEST(Blob, HierarchyMatchesEveryElement) {
    // A few hundred components: spheres and cylinders, some negative, some with transforms of
    // their own, some textured. The bounding hierarchy must find what a loop over all elements
    // finds: the same hits, normals, inside answers and texture blends.
    std::mt19937_64 rng(7);
    auto uni = [&](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(rng);
    };
    auto in_box = [&](double h) { return Vec3(uni(-h, h), uni(-h, h), uni(-h, h)); };
    scene::Blob b;
    b.threshold = 0.6;
    for (int i = 0; i < 300; ++i) {
        scene::BlobComponent c;
        c.center = in_box(6);
        c.cylinder = uni(0, 1) < 0.3;
        if (c.cylinder) c.apex = c.center + in_box(1.5);
        c.radius = uni(0.6, 1.6);
        c.strength = uni(0, 1) < 0.2 ? uni(-1.5, -0.3) : uni(0.5, 2);
        if (uni(0, 1) < 0.25) {
            c.transform = Transform::scale({uni(0.5, 1.5), uni(0.5, 1.5), uni(0.5, 1.5)})
                              .then(Transform::rotate_xyz_degrees(in_box(180)))
                              .then(Transform::translate(in_box(0.5)));
        }
        if (uni(0, 1) < 0.3) c.material = 1 + i % 3;
        b.components.push_back(c);
    }
    const char* why = nullptr;
    auto fast = render::make_blob(b, &why);
    auto slow = render::make_blob_exhaustive(b, &why);
    ASSERT_TRUE(fast && slow);
    EXPECT_EQ(fast->bounds().lo, slow->bounds().lo);
    EXPECT_EQ(fast->bounds().hi, slow->bounds().hi);
    auto same_t = [](double a, double c) {
        return std::fabs(a - c) <= 1e-12 * std::max(1.0, std::fabs(c));
    };
    size_t total_hits = 0, blended = 0;
    std::vector<render::TextureWeight> wf, ws;
    for (int k = 0; k < 600; ++k) {
        // Rays from outside towards the components, and rays starting among them.
        Vec3 o = k % 2 ? in_box(7) : normalize(in_box(1)) * 20;
        Vec3 d = k % 2 ? in_box(1) : in_box(6) - o;
        render::Ray r = ray(o, d);
        render::HitList hf, hs;
        fast->intersect_all(r, kInfinity, &hf);
        slow->intersect_all(r, kInfinity, &hs);
        ASSERT_EQ(hf.size(), hs.size()) << "ray " << k;
        total_hits += hf.size();
        for (size_t i = 0; i < hf.size(); ++i) {
            EXPECT_TRUE(same_t(hf[i].t, hs[i].t)) << hf[i].t << " vs " << hs[i].t;
            expect_vec(hf[i].ng, hs[i].ng, 1e-12);
            // The surface point's blend comes from the same elements with the same weights.
            ASSERT_EQ(fast->texture_blend(hf[i].p, &wf), slow->texture_blend(hs[i].p, &ws));
            ASSERT_EQ(wf.size(), ws.size());
            blended += wf.size() > 1;
            for (size_t j = 0; j < wf.size(); ++j) {
                EXPECT_EQ(wf[j].material, ws[j].material);
                EXPECT_NEAR(wf[j].weight, ws[j].weight, 1e-12);
            }
        }
        // The nearest hit and the shadow rays' hits agree with the full list.
        render::LocalHit nf;
        bool any = fast->intersect(r, kInfinity, &nf);
        ASSERT_EQ(any, !hs.empty());
        if (any) {
            EXPECT_TRUE(same_t(nf.t, hs[0].t));
        }
        render::HitList pf;
        fast->intersect_all_points(r, kInfinity, &pf);
        ASSERT_EQ(pf.size(), hs.size());
        for (size_t i = 0; i < pf.size(); ++i) EXPECT_TRUE(same_t(pf[i].t, hs[i].t));
        // Rays leaving the surface (shadow and reflected rays) start on a root they must skip.
        if (!hs.empty()) {
            render::Ray out = ray(hs[0].p, in_box(1));
            render::HitList of, os;
            fast->intersect_all(out, kInfinity, &of);
            slow->intersect_all(out, kInfinity, &os);
            ASSERT_EQ(of.size(), os.size());
            for (size_t i = 0; i < of.size(); ++i) EXPECT_TRUE(same_t(of[i].t, os[i].t));
            double tmax = uni(0, 20);
            render::LocalHit a, b;
            bool hit = fast->intersect(out, tmax, &a);
            ASSERT_EQ(hit, slow->intersect(out, tmax, &b));
            if (hit) {
                EXPECT_TRUE(same_t(a.t, b.t));
            }
        }
        // Shorter rays (shadow rays) end where they end.
        for (double tmax : {uni(0, 1), uni(0, 40)}) {
            render::HitList cf, cs;
            fast->intersect_all(r, tmax, &cf);
            slow->intersect_all(r, tmax, &cs);
            ASSERT_EQ(cf.size(), cs.size());
            bool hit = fast->intersect(r, tmax, &nf);
            ASSERT_EQ(hit, !cs.empty());
            if (hit) {
                EXPECT_TRUE(same_t(nf.t, cs[0].t));
                expect_vec(nf.ng, cs[0].ng, 1e-12);
            }
        }
    }
    EXPECT_GT(total_hits, 500u);
    EXPECT_GT(blended, 20u);
    size_t in = 0;
    for (int k = 0; k < 20000; ++k) {
        Vec3 p = in_box(7.5);
        bool f = fast->inside(p);
        ASSERT_EQ(f, slow->inside(p)) << p.x << " " << p.y << " " << p.z;
        in += f;
    }
    EXPECT_GT(in, 1000u);
    EXPECT_LT(in, 19000u);
}

TEST(SolidsParser, BlobComponentTextures) {
    auto sc = pov::testing::parse(
        "#declare B = blob { threshold 0.5\n"
        "  sphere { <1,0,0>, 2, 1 pigment { rgb <1,0,0> } translate x }\n"
        "  sphere { <-1,0,0>, 2, 1 }\n"
        "  cylinder { 0, y, 1, 1 texture { pigment { rgb <0,0,1> } } texture { finish { "
        "ambient 0.5 } } }\n"
        "  pigment { rgb 1 } }\n"
        "object { B }\n"
        "object { B translate <0,3,0> }");
    ASSERT_EQ(sc.objects.size(), 2u);
    const auto& b0 = std::get<scene::Blob>(sc.objects[0].shape);
    const auto& b1 = std::get<scene::Blob>(sc.objects[1].shape);
    ASSERT_EQ(b0.components.size(), 3u);
    EXPECT_EQ(b0.components[1].material, -1);
    ASSERT_GE(b0.components[0].material, 0);
    ASSERT_GE(b0.components[2].material, 0);
    const scene::Texture& red = sc.materials[b0.components[0].material].texture;
    EXPECT_EQ(red.pigment.color.rgb.r, 1);
    EXPECT_EQ(red.pigment.color.rgb.b, 0);
    // The component's translate after its pigment moves the texture along.
    EXPECT_NEAR(red.pigment.transform.point(Vec3(0, 0, 0)).x, 1, 1e-12);
    // A second texture is a layer over the first.
    const scene::Texture& blue = sc.materials[b0.components[2].material].texture;
    EXPECT_EQ(blue.layers.size(), 1u);
    // The moved copy has moved copies of the component textures; the first keeps its own.
    ASSERT_NE(b1.components[0].material, b0.components[0].material);
    const scene::Texture& moved = sc.materials[b1.components[0].material].texture;
    EXPECT_NEAR(moved.pigment.transform.point(Vec3(0, 0, 0)).y, 3, 1e-12);
    EXPECT_NEAR(red.pigment.transform.point(Vec3(0, 0, 0)).y, 0, 1e-12);
}

// ---- height_field ------------------------------------------------------------------------

TEST(HeightField, GreyImageHeights) {
    // 3x3 PGM, all 0 except the centre 255: a pyramid of height 255*257/65536.
    auto dir = std::filesystem::temp_directory_path() /
               ("glint_hf_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::string path = (dir / "hf.pgm").string();
    {
        std::ofstream f(path);
        f << "P2\n3 3\n255\n0 0 0\n0 255 0\n0 0 0\n";
    }
    scene::HeightField hf;
    hf.file = hf.resolved_path = path;
    auto g = build_one(hf);
    Hit h;
    const double top = 255.0 * 257 / 65536;
    ASSERT_TRUE(g->intersect(ray({0.5, 5, 0.5}, {0, -1, 0}), &h));
    EXPECT_NEAR(h.p.y, top, 1e-9);
    // Cell (0, 0) rises only in its upper triangle, towards the centre (POV-Ray's diagonal).
    ASSERT_TRUE(g->intersect(ray({0.375, 5, 0.375}, {0, -1, 0}), &h));
    EXPECT_NEAR(h.p.y, top / 2, 1e-9);
    EXPECT_GT(h.ng.y, 0);
    EXPECT_TRUE(inside(hf, {0.5, 0.5, 0.5}));
    EXPECT_FALSE(inside(hf, {0.1, 0.5, 0.1}));
    std::filesystem::remove_all(dir);
}

// ---- poly --------------------------------------------------------------------------------

TEST(Poly, SphereAndTorusQuartic) {
    scene::Poly s;
    s.order = 2;
    s.coefficients = {1, 0, 0, 0, 1, 0, 0, 1, 0, -1};
    auto g = build_one(s);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, -5, 0}, {0, 1, 0}), &h));
    EXPECT_NEAR(h.t, 4, 1e-9);
    expect_vec(h.ng, {0, -1, 0}, 1e-9);
    EXPECT_TRUE(inside(s, {0, 0, 0}));
    // Torus R = 2, r = 0.5 from its quartic through the parser (quartic { ... }).
    auto sc = pov::testing::parse(
        "quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -8.5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 2,"
        " 0, 7.5, 0, 0, 0, 0, 1, 0, -8.5, 0, 14.0625> }");
    ASSERT_EQ(sc.objects.size(), 1u);
    g = build_one(sc.objects[0].shape);
    ASSERT_TRUE(g->intersect(ray({-5, 0, 0}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 2.5, 1e-9);
    EXPECT_EQ(test::hit_depths(sc.objects[0].shape, ray({-5, 0, 0}, {1, 0, 0})).size(), 4u);
}

// ---- importer ----------------------------------------------------------------------------

TEST(SolidsParser, MessagesForMisuse) {
    using pov::testing::error_of;
    EXPECT_EQ(error_of("prism { 0, 1, 2, <0, 0>, <1, 0> }"),
              "1:15: prism needs at least 3 points");
    EXPECT_EQ(error_of("prism { bezier_spline 0, 1, 5, <0,0>,<1,0>,<1,1>,<0,1>,<0,0> }"),
              "1:29: prism with bezier_spline needs 4 points per segment");
    EXPECT_EQ(error_of("polygon { 2, <0,0,0>, <1,0,0> }"), "1:11: polygon needs at least 3 points");
    EXPECT_EQ(error_of("sor { 3, <0,0>, <1,1>, <1,2> }"), "1:7: sor needs at least 4 points");
    EXPECT_EQ(error_of("sor { 4, <1,0>, <1,1>, <1,0.5>, <1,2> }"),
              "1:24: sor point 3 is not higher than the point before it");
    EXPECT_EQ(error_of("lathe { 3, <0,0>, <-1,1>, <0,2> }"),
              "1:19: lathe point 2 has a negative radius");
    EXPECT_EQ(error_of("blob { threshold 0.5 }"), "1:1: blob needs at least one component");
    EXPECT_EQ(error_of("blob { cylinder { <0,0,0>, <0,0,0>, 1, 1 } }"),
              "1:8: degenerate cylindrical component in blob (its ends coincide)");
    EXPECT_EQ(error_of("superellipsoid { <0, 1> }"),
              "1:18: superellipsoid exponents <e, n> must be positive");
    EXPECT_EQ(error_of("poly { 1, <1, 2, 3, 4> }"), "1:8: order of poly is out of range (2 to 35)");
    EXPECT_EQ(error_of("cubic { <1, 2, 3> }"),
              "1:9: cubic of order 3 needs 20 coefficients, got 3");
    EXPECT_EQ(error_of("height_field { png \"no_such_file.png\" }"),
              "1:20: cannot find the file 'no_such_file.png'");
}

TEST(SolidsParser, BodiesIntoTheIr) {
    auto sc = pov::testing::parse(
        "prism { conic_sweep cubic_spline 1, 0.2, 7, <-1,1>, <-1,-1>, <1,-1>, <1,1>, <-1,1>,"
        " <-1,-1>, <1,-1> open }\n"
        "prism { 0, 1, 3, <0,0>, <1,0>, <0,1> }\n"
        "blob { threshold 0.4 sphere { <1,0,0>, 2, strength 3 scale 2 } "
        "cylinder { 0, y, 1, -1 } component 1, 2, <0,1,0> }\n"
        "polynomial { 2, xyz(2,0,0): 1, xyz(0,0,0): -1 }\n"
        "height_field { function 8, 8 { x } translate y }\n"
        "prism { -0.5, 0.5, 4 <-1, -0.3>, <1, 0>, <-1, 0.3>, <-1, -0.3> }");  // no comma
    ASSERT_EQ(sc.objects.size(), 6u);
    EXPECT_EQ(std::get<scene::HeightField>(sc.objects[4].shape).grid_w, 8);
    EXPECT_EQ(std::get<scene::Prism>(sc.objects[5].shape).points.size(), 4u);
    const auto& p = std::get<scene::Prism>(sc.objects[0].shape);
    EXPECT_TRUE(p.conic);
    EXPECT_TRUE(p.open);
    EXPECT_EQ(p.spline, scene::SplineType::Cubic);
    EXPECT_EQ(p.height1, 0.2);  // swapped into order
    EXPECT_EQ(p.height2, 1);
    // A linear prism that is not closed gets its first point appended.
    EXPECT_EQ(std::get<scene::Prism>(sc.objects[1].shape).points.size(), 4u);
    const auto& b = std::get<scene::Blob>(sc.objects[2].shape);
    EXPECT_EQ(b.threshold, 0.4);
    ASSERT_EQ(b.components.size(), 3u);
    EXPECT_EQ(b.components[0].strength, 3);
    EXPECT_FALSE(b.components[0].transform.is_identity());
    EXPECT_TRUE(b.components[1].cylinder);
    EXPECT_EQ(b.components[1].strength, -1);
    EXPECT_EQ(b.components[2].radius, 2);
    const auto& q = std::get<scene::Poly>(sc.objects[3].shape);
    EXPECT_EQ(q.coefficients.front(), 1);
    EXPECT_EQ(q.coefficients.back(), -1);
}

}  // namespace
}  // namespace glint
