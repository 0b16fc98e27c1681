// POV-Ray photons in the classic renderer (render/gi/photon_map.h, gi/classic_photons.cpp):
// the map's nearest-photon gather against a brute-force search, and end to end the light a
// clear slab lets through arriving as photons with the energy of the direct light it replaces,
// the same at any thread count.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "core/log.h"
#include "render/gi/photon_map.h"
#include "render/render.h"
#include "unit/pov_test_util.h"

namespace glint::render {
namespace {

TEST(PhotonMap, GathersTheNearestPhotonsOfABruteForceSearch) {
    // A jittered grid of photons on the plane y = 0.
    std::vector<Photon> photons;
    uint64_t s = 12345;
    auto rnd = [&] {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(s >> 11) / 9007199254740992.0;
    };
    for (int i = 0; i < 60; ++i)
        for (int j = 0; j < 60; ++j)
            photons.push_back({Vec3(i * 0.1 + 0.05 * rnd(), 0, j * 0.1 + 0.05 * rnd()),
                               Vec3(0, 1, 0), Color(1)});
    scene::Photons settings;
    settings.radius = 0.35;
    settings.gather_min = 20;
    settings.gather_max = 30;
    const PhotonMap map(photons, settings);
    EXPECT_EQ(map.size(), photons.size());
    EXPECT_DOUBLE_EQ(map.gather_radius(), 0.35);
    for (const Vec3& p : {Vec3(3, 0, 3), Vec3(0.02, 0, 5.5), Vec3(4.4, 0, 1.23)}) {
        PhotonGather g;
        const Vec3 up(0, 1, 0);
        map.gather(p, &up, &g);
        // Brute force: all photons within the radius if fewer than 30, else the 30 nearest
        // and the disc they span.
        std::vector<double> d;
        for (const Photon& ph : photons) d.push_back(length(ph.p - p));
        std::sort(d.begin(), d.end());
        const size_t within = std::lower_bound(d.begin(), d.end(), 0.35) - d.begin();
        ASSERT_EQ(g.photons.size(), std::min<size_t>(within, 30)) << p.x;
        const double reach = within >= 30 ? d[29] : 0.35;
        for (const Photon* ph : g.photons) EXPECT_LE(length(ph->p - p), reach + 1e-12);
        EXPECT_NEAR(g.radius, reach, 1e-12);
    }
    // Where fewer than gather's minimum lie within the radius the gather widens once.
    PhotonGather edge;
    const Vec3 up(0, 1, 0);
    map.gather(Vec3(-0.5, 0, -0.5), &up, &edge);
    EXPECT_GT(edge.radius, 0.35);
}

TEST(PhotonMap, EstimatesItsRadiusFromTheDensity) {
    // A uniform grid of density 100 per unit area: gather max 50 needs r = sqrt(50/(100 pi)),
    // which POV-Ray's estimate then widens by 1 + 20 x (the share of sample photons, here
    // those near the grid's edges, whose density is under 70% of the average).
    std::vector<Photon> photons;
    for (int i = 0; i < 200; ++i)
        for (int j = 0; j < 200; ++j)
            photons.push_back({Vec3(i * 0.1, 0, j * 0.1), Vec3(0, 1, 0), Color(1)});
    scene::Photons settings;
    settings.gather_max = 50;
    const PhotonMap map(photons, settings);
    const double base = std::sqrt(50 / (100 * kPi));
    EXPECT_GE(map.gather_radius(), base * 0.98);
    EXPECT_LE(map.gather_radius(), base * 1.5);
}

// A point light above a floor; a clear slab (ior 1, filter through a red tint) on a thin
// shelf of air between them is a photon target. Its shadow is full, and the light it lets
// through comes back as photons.
RenderResult slab(int threads) {
    const std::string text =
        "#version 3.7;\n"
        "global_settings { photons { spacing 0.01 jitter 0 autostop 0 } }\n"
        "camera { orthographic location <0, 10, 0> look_at 0 right 4*x up 3*z }\n"
        "light_source { <0, 20, 0> rgb 1 photons { refraction on } }\n"
        "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
        "box { <-1, 1, -1>, <0, 1.1, 1> pigment { rgbf <1, 0.5, 0.25, 1> }\n"
        "  finish { ambient 0 diffuse 0 } interior { ior 1 } photons { target collect off } }\n";
    RenderOptions o;
    o.width = 80;
    o.height = 60;
    o.threads = threads;
    o.integrator = IntegratorKind::Whitted;
    Diagnostics diag;
    return render(pov::testing::parse(text), o, diag);
}

TEST(ClassicPhotons, LightThroughAClearSlabArrivesWithItsEnergy) {
    const Image img = slab(2).image;
    // Under the slab (x in [-1, 0]: image columns 40-60, the camera looking down has +x to
    // the left) against the open floor far from it.
    auto mean = [&](int x0, int x1, int c) {
        double s = 0;
        int n = 0;
        for (int y = 20; y < 40; ++y)
            for (int x = x0; x < x1; ++x, ++n) s += img.pixel(x, y)[c];
        return s / n;
    };
    const double open = mean(4, 16, 0);
    EXPECT_NEAR(open, 1.0, 0.01);  // the direct light: cos ~ 1, no fading
    // Through the slab: the light crossed two filtering surfaces and arrives as photons (the
    // shadow ray is blocked); the camera sees that floor through the same two surfaces, so
    // the filter counts four times: 1, 0.5^4, 0.25^4.
    EXPECT_NEAR(mean(44, 56, 0) / open, 1.0, 0.05);
    EXPECT_NEAR(mean(44, 56, 1) / open, 0.0625, 0.0625 * 0.05);
    EXPECT_NEAR(mean(44, 56, 2) / open, 0.00390625, 0.00390625 * 0.05);
    EXPECT_EQ(slab(1).image.rgba, img.rgba);
}

TEST(ClassicPhotons, SaveFileAndLoadFileGiveTheSameImage) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("glint_photon_file_" +
                                                      std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string file = (dir / "slab.ph").string();
    auto scene = [&](const std::string& photons) {
        return "#version 3.7;\n"
               "global_settings { photons { " + photons + " } }\n"
               "camera { orthographic location <0, 10, 0> look_at 0 right 4*x up 3*z }\n"
               "light_source { <0, 20, 0> rgb 1 photons { refraction on } }\n"
               "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
               "box { <-1, 1, -1>, <0, 1.1, 1> pigment { rgbf <1, 0.5, 0.25, 1> }\n"
               "  finish { ambient 0 diffuse 0 } interior { ior 1 } "
               "photons { target collect off } }\n";
    };
    RenderOptions o;
    o.width = 40;
    o.height = 30;
    Diagnostics diag;
    const Image saved =
        render(pov::testing::parse(scene("spacing 0.01 jitter 0 autostop 0 save_file \"" +
                                         file + "\"")),
               o, diag)
            .image;
    ASSERT_TRUE(fs::exists(file));
    EXPECT_FALSE(fs::exists(file + ".tmp"));
    // Loaded, the photons are the saved ones, whatever the spacing says now.
    const Image loaded =
        render(pov::testing::parse(scene("spacing 0.5 load_file \"" + file + "\"")), o, diag)
            .image;
    EXPECT_EQ(loaded.rgba, saved.rgba);
    const Image fewer =
        render(pov::testing::parse(scene("spacing 0.5")), o, diag).image;
    EXPECT_NE(fewer.rgba, saved.rgba);
    // A file that is not one, or none at all: an error at the photons block.
    std::ofstream(dir / "bad.ph") << "not photons";
    for (const std::string& bad : {(dir / "bad.ph").string(), (dir / "none.ph").string()}) {
        try {
            render(pov::testing::parse(scene("load_file \"" + bad + "\"")), o, diag);
            ADD_FAILURE() << bad;
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::MissingFile) << e.what();
            EXPECT_EQ(e.loc().line, 2) << e.what();
            EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
        }
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace glint::render
