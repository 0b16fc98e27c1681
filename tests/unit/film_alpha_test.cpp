// The film's alpha (Blender's Film > Transparent and holdouts, as Cycles 3.4 computes them):
// alpha = 1 - the share of the camera's view that reaches the world through nothing but
// transparent surfaces (transparent film) or meets a holdout; that share adds no colour.
#include <gtest/gtest.h>

#include <cmath>

#include "core/log.h"
#include "render/render.h"
#include "unit/path_test_util.h"

namespace glint::render {
namespace {

using path_test::lambert;

// A unit sphere filling the middle of a 16 x 12 image, in a white environment.
scene::Scene sphere_scene(const scene::Material& m) {
    scene::Scene s;
    s.camera.location = Vec3(0, 0, -4);
    s.materials.push_back(m);
    scene::Object o;
    o.shape = scene::Sphere{Vec3(0, 0, 0), 1};
    o.material = 0;
    s.objects.push_back(o);
    s.background = scene::ColorFT(Color(1, 1, 1));
    return s;
}

RenderOptions options(bool transparent) {
    RenderOptions o = path_test::path_options(16, 12, 64, 8);
    o.film_transparent = transparent;
    return o;
}

const float* centre(const Image& img) { return img.pixel(8, 6); }
const float* corner(const Image& img) { return img.pixel(0, 0); }

TEST(FilmAlpha, OpaqueFilmKeepsAlphaOne) {
    Diagnostics diag;
    const RenderResult r = render(sphere_scene(lambert(Color(0.5, 0.5, 0.5))), options(false), diag);
    EXPECT_FALSE(r.alpha);
    for (size_t i = 3; i < r.image.rgba.size(); i += 4) ASSERT_EQ(r.image.rgba[i], 1.0f);
    EXPECT_NEAR(corner(r.image)[0], 1.0, 1e-6);  // the world is drawn
}

TEST(FilmAlpha, TransparentFilmHidesTheWorld) {
    Diagnostics diag;
    const RenderResult r = render(sphere_scene(lambert(Color(0.5, 0.5, 0.5))), options(true), diag);
    EXPECT_TRUE(r.alpha);
    EXPECT_EQ(corner(r.image)[3], 0.0f);
    EXPECT_EQ(corner(r.image)[0], 0.0f);  // no world colour either
    EXPECT_EQ(centre(r.image)[3], 1.0f);
    // The sphere is still lit by the world it does not show: Lambert 0.5 under a white
    // environment, unoccluded, is 0.5.
    EXPECT_NEAR(centre(r.image)[0], 0.5, 0.05);
}

TEST(FilmAlpha, SeeThroughSurfaceLeavesItsTransparency) {
    // Alpha 0.3: 70% of the camera's view passes to the world (stochastically, 64 samples).
    scene::Material m = lambert(Color(0.5, 0.5, 0.5));
    m.pbr.alpha = 0.3;
    Diagnostics diag;
    RenderOptions o = options(true);
    o.spp = 1024;
    const RenderResult r = render(sphere_scene(m), o, diag);
    double sum = 0;
    int n = 0;
    for (int y = 5; y <= 6; ++y)
        for (int x = 7; x <= 8; ++x) sum += r.image.pixel(x, y)[3], ++n;
    // Both sides of the sphere: 1 - 0.7^2 = 0.51 of the view is stopped.
    EXPECT_NEAR(sum / n, 0.51, 0.03);
}

TEST(FilmAlpha, HoldoutObjectIsBlackAndTransparent) {
    scene::Scene s = sphere_scene(lambert(Color(0.5, 0.5, 0.5)));
    s.objects[0].holdout = true;
    Diagnostics diag;
    const RenderResult opaque_film = render(s, options(false), diag);
    // Cycles: a holdout cuts a hole in the image whether or not the film is transparent.
    EXPECT_TRUE(opaque_film.alpha);
    EXPECT_EQ(centre(opaque_film.image)[3], 0.0f);
    EXPECT_EQ(centre(opaque_film.image)[0], 0.0f);
    EXPECT_EQ(corner(opaque_film.image)[3], 1.0f);  // the world stays, opaque
    EXPECT_NEAR(corner(opaque_film.image)[0], 1.0, 1e-6);
    const RenderResult film = render(s, options(true), diag);
    EXPECT_EQ(centre(film.image)[3], 0.0f);
    EXPECT_EQ(corner(film.image)[3], 0.0f);
}

}  // namespace
}  // namespace glint::render
