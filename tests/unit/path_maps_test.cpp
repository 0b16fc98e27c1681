// OBJ/MTL image maps in the path tracer (formats/obj/MTL.md): each map changes the render
// where it should, -o/-s move the lookup, bump and normal maps bend the shading normal.
// Scenes are a 6 x 6 quad filling an orthographic view, read through the OBJ importer.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <vector>

#include "core/log.h"
#include "formats/obj/obj_importer.h"
#include "render/bsdf/pov_to_pbr.h"
#include "render/render.h"

namespace glint::render {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 32;  // image width and height

double srgb(int byte) {
    const double v = byte / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

class PathMaps : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("glint-path-maps-" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    // An 8-bit PNG of w x h x channels from pixel(x, y, channel), row 0 at the top.
    std::string png(const std::string& name, int w, int h, int channels,
                    const std::function<int(int, int, int)>& pixel) {
        std::vector<uint8_t> data(static_cast<size_t>(w) * h * channels);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < channels; ++c)
                    data[(static_cast<size_t>(y) * w + x) * channels + c] =
                        static_cast<uint8_t>(pixel(x, y, c));
        const std::string path = (dir_ / name).string();
        auto out = OIIO::ImageOutput::create(path);
        OIIO::ImageSpec spec(w, h, channels, OIIO::TypeDesc::UINT8);
        EXPECT_TRUE(out && out->open(path, spec));
        out->write_image(OIIO::TypeDesc::UINT8, data.data());
        out->close();
        return path;
    }

    // The quad (-3..3)^2 at z = 0 facing the camera at z = -5, uv (0, 0) at its lower left,
    // with the material `mtl` (the body of `newmtl m`); black background, no lights.
    scene::Scene quad(const std::string& mtl) {
        std::ofstream(dir_ / "q.mtl") << "newmtl m\n" << mtl << "\n";
        std::ofstream(dir_ / "q.obj") << "mtllib q.mtl\n"
                                         "v -3 -3 0\nv -3 3 0\nv 3 3 0\nv 3 -3 0\n"
                                         "vt 0 0\nvt 0 1\nvt 1 1\nvt 1 0\n"
                                         "usemtl m\nf 1/1 2/2 3/3 4/4\n";
        scene::Scene s;
        s.global.assumed_gamma = 1.0;
        obj::import_obj((dir_ / "q.obj").string(), s, Transform{}, -1, diag_);
        s.camera.kind = scene::CameraKind::Orthographic;
        s.camera.location = Vec3(0, 0, -5);
        s.camera.direction = Vec3(0, 0, 1);
        s.camera.right = Vec3(6, 0, 0);
        s.camera.up = Vec3(0, 6, 0);
        s.background = scene::ColorFT(Color(0, 0, 0));
        return s;
    }

    Image render_path(const scene::Scene& s, int spp = 4, int depth = 4) {
        RenderOptions o;
        o.width = o.height = kSize;
        o.integrator = IntegratorKind::Path;
        o.spp = spp;
        o.max_depth = depth;
        o.threads = 2;
        RenderResult r = render(s, o, diag_);
        EXPECT_EQ(r.nonfinite_paths, 0u);
        return r.image;
    }

    // The pixel whose centre sees surface uv (u, v).
    static const float* at(const Image& img, double u, double v) {
        const int x = std::clamp(static_cast<int>(u * kSize), 0, kSize - 1);
        const int y = std::clamp(static_cast<int>((1 - v) * kSize), 0, kSize - 1);
        return img.pixel(x, y);
    }

    // Mean of channel c over the pixels with u in [u0, u1], v in [0.3, 0.7].
    static double mean(const Image& img, double u0, double u1, int c = 0) {
        double sum = 0;
        int n = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const double u = (x + 0.5) / kSize, v = 1 - (y + 0.5) / kSize;
                if (u < u0 || u > u1 || v < 0.3 || v > 0.7) continue;
                sum += img.pixel(x, y)[c];
                ++n;
            }
        return n > 0 ? sum / n : 0;
    }

    void expect_rgb(const float* p, double r, double g, double b, double tol = 1e-5) {
        EXPECT_NEAR(p[0], r, tol);
        EXPECT_NEAR(p[1], g, tol);
        EXPECT_NEAR(p[2], b, tol);
    }

    // 8 x 1: the left half red, the right half (0, 128, 255).
    std::string halves() {
        return png("halves.png", 8, 1, 3, [](int x, int, int c) {
            static const int left[3] = {255, 0, 0}, right[3] = {0, 128, 255};
            return x < 4 ? left[c] : right[c];
        });
    }

    fs::path dir_;
    Diagnostics diag_;
};

TEST_F(PathMaps, EmissionMapShowsOnAnEmitterWithoutLights) {
    halves();
    // As Blender writes a textured Emission: map_Ke without Ke; sRGB-decoded, strength 1.
    const Image img = render_path(quad("Kd 0 0 0\nKs 0 0 0\nmap_Ke halves.png"));
    expect_rgb(at(img, 0.25, 0.5), 1, 0, 0);
    expect_rgb(at(img, 0.75, 0.5), 0, srgb(128), 1);
    // v = 0 is the image's bottom row (OBJ and Blender): top half red, bottom half blue.
    png("rows.png", 1, 8, 3, [](int, int y, int c) { return (y < 4 ? c == 0 : c == 2) ? 255 : 0; });
    const Image rows = render_path(quad("Kd 0 0 0\nKs 0 0 0\nmap_Ke rows.png"));
    expect_rgb(at(rows, 0.5, 0.75), 1, 0, 0);
    expect_rgb(at(rows, 0.5, 0.25), 0, 0, 1);
}

TEST_F(PathMaps, ScaleAndOffsetMoveTheLookup) {
    halves();
    // uv * s + o: -s 2 repeats the halves twice across the quad.
    Image img = render_path(quad("Kd 0 0 0\nKs 0 0 0\nmap_Ke -s 2 1 1 halves.png"));
    expect_rgb(at(img, 0.125, 0.5), 1, 0, 0);
    expect_rgb(at(img, 0.375, 0.5), 0, srgb(128), 1);
    expect_rgb(at(img, 0.625, 0.5), 1, 0, 0);
    // -o 0.5 swaps the halves.
    img = render_path(quad("Kd 0 0 0\nKs 0 0 0\nmap_Ke -o 0.5 0 0 halves.png"));
    expect_rgb(at(img, 0.25, 0.5), 0, srgb(128), 1);
    expect_rgb(at(img, 0.75, 0.5), 1, 0, 0);
}

TEST_F(PathMaps, AlphaMaskLetsTheBackgroundThroughWhereItIsZero) {
    png("mask.png", 8, 1, 1, [](int x, int, int) { return x < 4 ? 0 : 255; });
    scene::Scene s = quad("Kd 0 0 0\nKs 0 0 0\nKe 1 1 1\nmap_d mask.png");
    s.background = scene::ColorFT(Color(0.2, 0.4, 0.6));
    const Image img = render_path(s);
    for (double v : {0.2, 0.5, 0.8}) {
        expect_rgb(at(img, 0.2, v), 0.2, 0.4, 0.6);  // mask 0: exactly the background
        expect_rgb(at(img, 0.8, v), 1, 1, 1);        // mask 1: exactly the emitter
    }
}

TEST_F(PathMaps, BaseColorMapIsSrgbDecodedUnderUniformLight) {
    png("gray.png", 4, 4, 3, [](int, int, int) { return 128; });
    // A Lambertian quad under a uniform white sky reflects its albedo.
    scene::Scene s = quad("Kd 1 1 1\nKs 0 0 0\nmap_Kd gray.png");
    s.background = scene::ColorFT(Color(1, 1, 1));
    const Image img = render_path(s, 64, 2);
    EXPECT_NEAR(mean(img, 0.2, 0.8), srgb(128), 0.01 * srgb(128));  // not 128/255 = 0.502
}

TEST_F(PathMaps, MetallicAndRoughnessMapsChangeTheReflectance) {
    png("mask.png", 8, 1, 1, [](int x, int, int) { return x < 4 ? 0 : 255; });
    auto lit = [&](const std::string& mtl) {
        scene::Scene s = quad(mtl);
        scene::Light l;
        l.location = Vec3(-2, 1, -6);
        l.color = Color(20, 20, 20);
        s.lights.push_back(l);
        return render_path(s);
    };
    // map_Pm: 0 on the left, 1 on the right; each half equals the constant it stands for.
    const std::string base = "Kd 0.5 0.5 0.5\nKs 0.5 0.5 0.5\nPr 0\n";
    const Image pm = lit(base + "map_Pm mask.png");
    const Image dielectric = lit(base + "Pm 0");
    const Image metal = lit(base + "Pm 1");
    const double left = mean(pm, 0.1, 0.4), right = mean(pm, 0.6, 0.9);
    EXPECT_GT(left, 0.05);
    EXPECT_NEAR(left, mean(dielectric, 0.1, 0.4), 1e-6);
    EXPECT_NEAR(right, mean(metal, 0.6, 0.9), 1e-6);
    EXPECT_LT(right, 1e-6);  // a smooth metal only mirrors the black background
    // map_Pr on a metal: smooth (a mirror of black) on the left, rough (lit) on the right.
    const Image pr = lit("Kd 0.9 0.9 0.9\nKs 0.5 0.5 0.5\nPm 1\nmap_Pr mask.png");
    const Image rough = lit("Kd 0.9 0.9 0.9\nKs 0.5 0.5 0.5\nPm 1\nPr 1");
    EXPECT_LT(mean(pr, 0.1, 0.4), 1e-6);
    EXPECT_GT(mean(pr, 0.6, 0.9), 0.01);
    EXPECT_NEAR(mean(pr, 0.6, 0.9), mean(rough, 0.6, 0.9), 1e-6);
}

TEST_F(PathMaps, SpecularAndExponentMapsReplaceTheirConstants) {
    png("one.png", 4, 4, 1, [](int, int, int) { return 255; });
    png("quarter.png", 4, 4, 1, [](int, int, int) { return 64; });
    auto lit = [&](const std::string& mtl) {
        scene::Scene s = quad(mtl);
        scene::Light l;
        l.location = Vec3(0, 0, -6);
        s.lights.push_back(l);
        return mean(render_path(s), 0.3, 0.7);
    };
    // map_Ks = 1 is Ks 1; map_Ns of value v is Ns = 1000 v (roughness 1 - sqrt(v)).
    EXPECT_NEAR(lit("Kd 0.2 0.2 0.2\nNs 250\nmap_Ks one.png"), lit("Kd 0.2 0.2 0.2\nNs 250\nKs 1 1 1"),
                1e-6);
    EXPECT_NEAR(lit("Kd 0.2 0.2 0.2\nKs 1 1 1\nmap_Ns quarter.png"),
                lit("Kd 0.2 0.2 0.2\nKs 1 1 1\nNs " + std::to_string(1000 * 64 / 255.0)), 1e-6);
    EXPECT_GT(std::fabs(lit("Kd 0.2 0.2 0.2\nKs 1 1 1\nmap_Ns quarter.png") -
                        lit("Kd 0.2 0.2 0.2\nKs 1 1 1\nNs 900")),
              1e-3);
}

TEST_F(PathMaps, BumpRampTiltsTheNormalByItsSlope) {
    // Heights i / 255 over 256 texels: dh/du = 256 / 255 per unit of u, and the quad is 6
    // wide, so -bm k tilts the normal by atan(k (256 / 255) / 6) towards -x. k is chosen for
    // tan = 0.75: cos = 0.8.
    png("ramp.png", 256, 1, 1, [](int x, int, int) { return x; });
    const double k = 6 * 0.75 * 255 / 256;
    auto lit = [&](const std::string& mtl, Vec3 from) {
        scene::Scene s = quad(mtl);
        scene::Light l;
        l.parallel = true;
        l.location = from;
        l.point_at = Vec3(0, 0, 0);
        s.lights.push_back(l);
        return mean(render_path(s, 1, 1), 0.3, 0.7);
    };
    const std::string flat = "Kd 1 1 1\nKs 0 0 0\n";
    const std::string bumped = flat + "bump -bm " + std::to_string(k) + " ramp.png";
    // Light along the flat normal: the bumped surface gets cos(tilt) = 0.8 of it.
    const Vec3 front(0, 0, -10), tilted(-6, 0, -8);
    EXPECT_NEAR(lit(bumped, front) / lit(flat, front), 0.8, 1e-4);
    // Light along the tilted normal (-0.6, 0, -0.8): the bumped surface faces it.
    EXPECT_NEAR(lit(bumped, tilted) / lit(flat, tilted), 1 / 0.8, 1e-4);
}

TEST_F(PathMaps, NormalMapIsDecodedInTheTangentFrame) {
    // A colored map_Bump is a tangent-space normal map (what Blender writes). (204, 128, 230)
    // decodes to about (0.6, 0, 0.8): tangent +x (dpdu), normal -z.
    const std::string file = png("n.png", 4, 4, 3, [](int, int, int c) {
        static const int rgb[3] = {204, 128, 230};
        return rgb[c];
    });
    scene::Pbr pbr;
    pbr.derived = false;
    pbr.bump_map.file = file;
    pbr.bump_map.resolved_path = file;
    TextureCache cache(ImageGamma{});
    const Vec3 n(0, 0, -1), dpdu(2, 0, 0), dpdv(0, 3, 0);
    const Vec3 c(2 * 204 / 255.0 - 1, 2 * 128 / 255.0 - 1, 2 * 230 / 255.0 - 1);
    for (double strength : {1.0, 0.5}) {
        pbr.bump_map.bump_multiplier = strength;
        const PbrMaps maps = prepare_pbr_maps(pbr, cache);
        EXPECT_TRUE(maps.normal_map);
        const Vec3 m = Vec3(c.x, c.y, 0) + n * c.z;  // T = +x, B = +y (dpdv's side)
        const Vec3 want = normalize(n + (m - n) * strength);
        const Vec3 got = mapped_normal(maps, Vec2(0.3, 0.6), n, dpdu, dpdv);
        EXPECT_NEAR(got.x, want.x, 1e-6);
        EXPECT_NEAR(got.y, want.y, 1e-6);
        EXPECT_NEAR(got.z, want.z, 1e-6);
        // Without tangents (no uvs) the normal stays.
        const Vec3 same = mapped_normal(maps, Vec2(0.3, 0.6), n, Vec3(), Vec3());
        EXPECT_EQ(same.z, -1.0);
    }
}

TEST_F(PathMaps, DataMapsAreLinearAndColorMapsSrgb) {
    const std::string file = png("g.png", 2, 2, 1, [](int, int, int) { return 128; });
    scene::Pbr pbr;
    pbr.derived = false;
    for (scene::PbrMap* m : {&pbr.base_color_map, &pbr.roughness_map}) {
        m->file = file;
        m->resolved_path = file;
    }
    TextureCache cache(ImageGamma{});
    const PbrMaps maps = prepare_pbr_maps(pbr, cache);
    const SurfacePbr s = pbr_surface(pbr, maps, Vec2(0.5, 0.5));
    EXPECT_NEAR(s.bsdf.base.r, srgb(128), 1e-6);
    EXPECT_NEAR(s.bsdf.roughness, 128 / 255.0, 1e-6);
    // An 8-bit sRGB file is held once, as stored: the color map decodes after its blend.
    EXPECT_EQ(cache.size(), 1u);
}

TEST_F(PathMaps, EightBitColorMapsBlendBeforeDecoding) {
    // Two texels, 0 and 255, side by side: halfway between their centres Cycles 3.4 blends the
    // stored bytes and decodes the blend, sRGB(127.5) = 0.212, where blending the decoded
    // texels would give 0.5 (the 70% seams of a wrapping texture).
    const std::string file = png("ramp.png", 2, 1, 3, [](int x, int, int) { return x ? 255 : 0; });
    scene::Pbr pbr;
    pbr.derived = false;
    pbr.base_color_map.file = pbr.base_color_map.resolved_path = file;
    TextureCache cache(ImageGamma{});
    const PbrMaps maps = prepare_pbr_maps(pbr, cache);
    ASSERT_TRUE(maps.base_color.decode_after);
    const double v = 0.5;
    const double mid = 127.5 / 255.0;
    const double expected = std::pow((mid + 0.055) / 1.055, 2.4);
    EXPECT_NEAR(pbr_surface(pbr, maps, Vec2(0.5, v)).bsdf.base.r, expected, 1e-6);
    // At a texel centre the texel itself, decoded.
    EXPECT_NEAR(pbr_surface(pbr, maps, Vec2(0.75, v)).bsdf.base.g, 1.0, 1e-6);
    EXPECT_NEAR(pbr_surface(pbr, maps, Vec2(0.25, v)).bsdf.base.b, 0.0, 1e-6);
}

TEST_F(PathMaps, SixteenBitColorMapsAreDecodedAtLoad) {
    // Cycles converts images of more than 8 bits to linear floats when it loads them; so does
    // glint, and blends the decoded texels.
    const std::string path = (dir_ / "ramp16.png").string();
    {
        const uint16_t data[6] = {0, 0, 0, 65535, 65535, 65535};
        auto out = OIIO::ImageOutput::create(path);
        OIIO::ImageSpec spec(2, 1, 3, OIIO::TypeDesc::UINT16);
        ASSERT_TRUE(out && out->open(path, spec));
        out->write_image(OIIO::TypeDesc::UINT16, data);
        out->close();
    }
    scene::Pbr pbr;
    pbr.derived = false;
    pbr.base_color_map.file = pbr.base_color_map.resolved_path = path;
    TextureCache cache(ImageGamma{});
    const PbrMaps maps = prepare_pbr_maps(pbr, cache);
    EXPECT_FALSE(maps.base_color.decode_after);
    EXPECT_NEAR(pbr_surface(pbr, maps, Vec2(0.5, 0.5)).bsdf.base.r, 0.5, 1e-6);
    EXPECT_EQ(cache.size(), 2u);  // read as stored first, then again decoded
}

TEST_F(PathMaps, MissingMapStillRenders) {
    const Image img = render_path(quad("Kd 0 0 0\nKs 0 0 0\nKe 0.5 0.5 0.5\nmap_Ke nowhere.png"));
    expect_rgb(at(img, 0.5, 0.5), 0.5, 0.5, 0.5);
    bool named = false;
    for (const auto& d : diag_.all()) named |= d.message.find("nowhere.png") != std::string::npos;
    EXPECT_TRUE(named);
}

}  // namespace
}  // namespace glint::render
