// Blender's view transforms (--view): finding config.ocio, checking names against it, and the
// display values and 8-bit codes of Blender 3.4's Standard and Filmic views. The codes marked
// "Blender" were read from PNGs that Blender 3.4.1 saved (tests/plugin/color_check.py checks
// every value of a larger image when Blender is installed). Tests that need Blender's config
// are skipped without it.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "io/color_encoding.h"
#include "io/image_output.h"
#include "image/image.h"

namespace fs = std::filesystem;
using glint::Error;
using glint::ErrorKind;
using glint::io::ViewSettings;

namespace {

const char* const kBlenderConfig = "/usr/share/blender/datafiles/colormanagement/config.ocio";

// Keeps $OCIO out of the way (and puts it back) so the search is the one under test.
class ScopedOcioEnv {
  public:
    explicit ScopedOcioEnv(const char* value) {
        if (const char* old = std::getenv("OCIO")) old_ = old, had_ = true;
        if (value)
            ::setenv("OCIO", value, 1);
        else
            ::unsetenv("OCIO");
    }
    ~ScopedOcioEnv() {
        if (had_)
            ::setenv("OCIO", old_.c_str(), 1);
        else
            ::unsetenv("OCIO");
    }
    ScopedOcioEnv(const ScopedOcioEnv&) = delete;
    ScopedOcioEnv& operator=(const ScopedOcioEnv&) = delete;

  private:
    std::string old_;
    bool had_ = false;
};

bool have_blender_config() { return fs::is_regular_file(kBlenderConfig); }

ViewSettings view(const std::string& name, const std::string& look = "", float exposure = 0,
                  float gamma = 1) {
    ViewSettings v;
    v.view = name;
    v.look = look;
    v.exposure = exposure;
    v.gamma = gamma;
    v.config_path = kBlenderConfig;
    return v;
}

// Display RGBA (straight alpha) of linear premultiplied pixels (one call: the config and its
// LUTs load once per call).
std::vector<float> shown(const ViewSettings& v, const std::vector<float>& rgba) {
    return glint::io::view_rgba(rgba, static_cast<int>(rgba.size() / 4), 1, v);
}

// Display values (red) of gray pixels.
std::vector<float> shown_grays(const ViewSettings& v, const std::vector<float>& grays) {
    std::vector<float> rgba;
    for (float g : grays) rgba.insert(rgba.end(), {g, g, g, 1.0f});
    std::vector<float> out = shown(v, rgba);
    std::vector<float> red;
    for (size_t i = 0; i < grays.size(); ++i) red.push_back(out[i * 4]);
    return red;
}

unsigned code(float v) { return glint::io::quantize(v, 255); }

ErrorKind kind_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.kind();
    }
    ADD_FAILURE() << "no glint::Error thrown";
    return ErrorKind::Render;
}

fs::path temp_dir(const std::string& name) {
    fs::path dir =
        fs::temp_directory_path() / ("glint_color_view_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

#define REQUIRE_BLENDER_CONFIG() \
    if (!have_blender_config()) GTEST_SKIP() << "Blender's config.ocio is not installed"

TEST(FindOcioConfig, GivenPathWinsAndMustExist) {
    ScopedOcioEnv env(nullptr);
    fs::path dir = temp_dir("given");
    fs::path cfg = dir / "my.ocio";
    std::ofstream(cfg) << "ocio_profile_version: 2\n";
    EXPECT_EQ(glint::io::find_ocio_config(cfg.string()), cfg.string());
    EXPECT_EQ(kind_of([&] { glint::io::find_ocio_config((dir / "none.ocio").string()); }),
              ErrorKind::MissingFile);
    fs::remove_all(dir);
}

TEST(FindOcioConfig, EnvironmentBeforeBlender) {
    fs::path dir = temp_dir("env");
    fs::path cfg = dir / "env.ocio";
    std::ofstream(cfg) << "ocio_profile_version: 2\n";
    {
        ScopedOcioEnv env(cfg.c_str());
        EXPECT_EQ(glint::io::find_ocio_config(""), cfg.string());
    }
    {
        ScopedOcioEnv env((dir / "missing.ocio").c_str());
        EXPECT_EQ(kind_of([] { glint::io::find_ocio_config(""); }), ErrorKind::MissingFile);
    }
    fs::remove_all(dir);
}

TEST(FindOcioConfig, FindsBlendersOwnOrNamesWhereItLooked) {
    ScopedOcioEnv env(nullptr);
    if (have_blender_config()) {
        EXPECT_EQ(glint::io::find_ocio_config(""), kBlenderConfig);
        return;
    }
    try {
        glint::io::find_ocio_config("");
        FAIL() << "found a config without Blender";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(kBlenderConfig), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("--ocio-config"), std::string::npos) << e.what();
    }
}

TEST(ResolveView, RejectsNamesTheConfigLacks) {
    REQUIRE_BLENDER_CONFIG();
    try {
        glint::io::resolve_view(view("Filmmic"));
        FAIL() << "accepted an unknown view";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Usage);
        EXPECT_NE(std::string(e.what()).find("Filmic"), std::string::npos) << e.what();
    }
    EXPECT_EQ(kind_of([] { glint::io::resolve_view(view("Filmic", "Ultra Contrast")); }),
              ErrorKind::Usage);
    EXPECT_EQ(kind_of([] { glint::io::resolve_view(view("Filmic", "", 0, 0)); }), ErrorKind::Usage);
    ViewSettings ok = glint::io::resolve_view(view("Filmic", "Medium High Contrast", 1.5f, 2.2f));
    EXPECT_EQ(ok.config_path, kBlenderConfig);
    EXPECT_NO_THROW(glint::io::resolve_view(view("Standard", "None")));
}

// Blender 3.4.1's 8-bit codes for gray linear values, read from PNGs it saved (dither 0,
// display sRGB, look None, exposure 0, gamma 1).
struct Measured {
    float linear;
    unsigned standard;
    unsigned filmic;
};

TEST(ViewRgba, GivesBlendersCodes) {
    REQUIRE_BLENDER_CONFIG();
    const Measured measured[] = {
        {0.0f, 0, 0},      {0.001f, 3, 4},    {0.01f, 25, 26},  {0.05f, 63, 70},
        {0.18f, 118, 128}, {0.5f, 188, 177},  {1.0f, 255, 206}, {2.0f, 255, 228},
        {8.0f, 255, 251},  {16.0f, 255, 255}, {-0.5f, 0, 0},
    };
    std::vector<float> grays;
    for (const Measured& m : measured) grays.push_back(m.linear);
    const std::vector<float> standard = shown_grays(view("Standard"), grays);
    const std::vector<float> filmic = shown_grays(view("Filmic"), grays);
    for (size_t i = 0; i < grays.size(); ++i) {
        EXPECT_EQ(code(standard[i]), measured[i].standard) << grays[i];
        EXPECT_EQ(code(filmic[i]), measured[i].filmic) << grays[i];
    }
}

TEST(ViewRgba, StandardIsTheSrgbCurve) {
    REQUIRE_BLENDER_CONFIG();
    std::vector<float> grays;
    for (int i = 0; i <= 512; ++i) grays.push_back(static_cast<float>(i) / 512.0f);
    const std::vector<float> s = shown_grays(view("Standard"), grays);
    for (size_t i = 0; i < grays.size(); ++i) {
        const float v = grays[i];
        const float srgb =
            v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
        // Blender's Standard view is a 1D LUT of the curve (srgb_inv.spi1d).
        EXPECT_NEAR(s[i], srgb, 2e-3f) << v;
    }
    const std::vector<float> px = shown(view("Standard"), {4.0f, -1.0f, 0.5f, 1.0f});
    EXPECT_EQ(code(px[0]), 255u);
    EXPECT_EQ(code(px[1]), 0u);
    EXPECT_EQ(code(px[2]), 188u);
    EXPECT_EQ(px[3], 1.0f);
}

TEST(ViewRgba, FilmicCompressesHighlights) {
    REQUIRE_BLENDER_CONFIG();
    std::vector<float> grays;
    for (float stops = -10.0f; stops <= 6.0f; stops += 0.25f)
        grays.push_back(0.18f * std::exp2(stops));
    const std::vector<float> f = shown_grays(view("Filmic"), grays);
    for (size_t i = 1; i < f.size(); ++i) EXPECT_GT(f[i], f[i - 1]) << grays[i];
    // Mid gray lands near the middle; 1.0, white under Standard, is well below white; five
    // stops over mid gray is not clipped yet.
    const std::vector<float> g = shown_grays(view("Filmic"), {0.18f, 1.0f, 5.76f, 0.02f});
    EXPECT_NEAR(g[0], 0.5f, 0.05f);
    EXPECT_LT(g[1], 0.85f);
    EXPECT_LT(g[2], 0.99f);
    // Looks change it: higher contrast darkens the shadows.
    EXPECT_LT(shown_grays(view("Filmic", "Very High Contrast"), {0.02f})[0], g[3]);
}

TEST(ViewRgba, ExposureScalesAndGammaIsAPower) {
    REQUIRE_BLENDER_CONFIG();
    const std::vector<float> v = {0.01f, 0.1f, 0.3f};
    const std::vector<float> exposed = shown_grays(view("Filmic", "", 1.0f), v);
    const std::vector<float> doubled = shown_grays(view("Filmic"), {0.02f, 0.2f, 0.6f});
    const std::vector<float> base = shown_grays(view("Standard"), v);
    const std::vector<float> gamma2 = shown_grays(view("Standard", "", 0.0f, 2.0f), v);
    for (size_t i = 0; i < v.size(); ++i) {
        EXPECT_NEAR(exposed[i], doubled[i], 1e-5f) << v[i];
        EXPECT_NEAR(gamma2[i], std::sqrt(base[i]), 2e-3f) << v[i];
    }
}

TEST(ViewRgba, PartialAlphaIsTransformedUnpremultiplied) {
    REQUIRE_BLENDER_CONFIG();
    for (const char* name : {"Standard", "Filmic"}) {
        // Premultiplied half coverage, opaque, and alpha 0 (its color transformed as it is).
        const std::vector<float> px = shown(view(name), {0.1f, 0.2f, 0.3f, 0.5f,  //
                                                         0.2f, 0.4f, 0.6f, 1.0f,  //
                                                         0.2f, 0.4f, 0.6f, 0.0f});
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(px[c], px[4 + c], 1e-6f) << name << c;
            EXPECT_NEAR(px[8 + c], px[4 + c], 1e-6f) << name << c;
        }
        EXPECT_EQ(px[3], 0.5f);
        EXPECT_EQ(px[11], 0.0f);
    }
}

TEST(WriteImage, ViewGivesRgbPngWithoutAlphaAndRgbaWithIt) {
    REQUIRE_BLENDER_CONFIG();
    fs::path dir = temp_dir("write");
    glint::Image img;
    img.width = 2;
    img.height = 1;
    img.rgba = {0.18f, 0.18f, 0.18f, 0.25f, 3.0f, 0.5f, 0.01f, 1.0f};
    glint::io::OutputEncoding enc;
    enc.view = view("Filmic");
    glint::io::write_image(img, (dir / "rgb.png").string(), enc);
    enc.alpha = true;
    glint::io::write_image(img, (dir / "rgba.png").string(), enc);
    bool alpha = true;
    // read_float_image refuses 8-bit files: they are display-encoded already.
    EXPECT_EQ(kind_of([&] { glint::io::read_float_image((dir / "rgb.png").string(), &alpha); }),
              ErrorKind::Usage);
    glint::io::write_image(img, (dir / "lin.exr").string(), enc);
    glint::Image back = glint::io::read_float_image((dir / "lin.exr").string(), &alpha);
    EXPECT_TRUE(alpha);
    EXPECT_EQ(back.rgba, img.rgba);  // float output ignores the view
    fs::remove_all(dir);
}

// 8-bit PNG keeps straight alpha, 16-bit TIFF premultiplied (associated) alpha: each as
// Blender writes it.
TEST(WriteImage, PngStraightTiffPremultiplied) {
    REQUIRE_BLENDER_CONFIG();
    fs::path dir = temp_dir("alpha");
    glint::Image img;
    img.width = 1;
    img.height = 1;
    img.rgba = {0.05f, 0.1f, 0.2f, 0.25f};  // premultiplied: straight (0.2, 0.4, 0.8)
    glint::io::OutputEncoding enc;
    enc.view = view("Filmic");
    enc.alpha = true;
    glint::io::write_image(img, (dir / "a.png").string(), enc);
    glint::io::write_image(img, (dir / "a.tif").string(), enc);
    auto raw = [](const fs::path& path, OIIO::TypeDesc type, void* data) {
        // The values as stored: OpenImageIO would premultiply a PNG's straight alpha.
        OIIO::ImageSpec config;
        config.attribute("oiio:UnassociatedAlpha", 1);
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path.string(), &config);
        ASSERT_TRUE(in);
        ASSERT_EQ(in->spec().nchannels, 4);
        ASSERT_TRUE(in->read_image(0, 0, 0, 4, type, data));
    };
    uint8_t png[4];
    uint16_t tif[4];
    raw(dir / "a.png", OIIO::TypeDesc::UINT8, png);
    raw(dir / "a.tif", OIIO::TypeDesc::UINT16, tif);
    const std::vector<float> straight = shown(view("Filmic"), {0.2f, 0.4f, 0.8f, 1.0f});
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(png[c], code(straight[c])) << c;
        EXPECT_NEAR(tif[c] / 65535.0f, straight[c] * 0.25f, 1e-4f) << c;
    }
    EXPECT_EQ(png[3], 64);  // 0.25 * 255 + 0.5
    EXPECT_EQ(tif[3], 16384);
    fs::remove_all(dir);
}

int run(const std::string& command) {
    int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(ConvertCommand, WritesTheViewAndRefusesLooseFlags) {
    REQUIRE_BLENDER_CONFIG();
    fs::path dir = temp_dir("cli");
    glint::Image img;
    img.width = 3;
    img.height = 1;
    img.rgba = {0.0f, 0.0f, 0.0f, 1.0f, 0.18f, 0.18f, 0.18f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f};
    glint::io::write_image(img, (dir / "in.exr").string(), glint::io::OutputEncoding{});
    const std::string glint = GLINT_BINARY;
    const std::string in = (dir / "in.exr").string();
    EXPECT_EQ(run(glint + " convert " + in + " -o " + (dir / "f.png").string() +
                  " --view Filmic --ocio-config " + kBlenderConfig),
              0);
    EXPECT_TRUE(fs::is_regular_file(dir / "f.png"));
    EXPECT_EQ(run(glint + " convert " + in + " -o " + (dir / "s.png").string() + " 2>/dev/null"),
              0);
    // --look without --view, an unknown view, and a missing config are usage/missing errors.
    EXPECT_EQ(run(glint + " convert " + in + " -o " + (dir / "x.png").string() +
                  " --look 'High Contrast' 2>/dev/null"),
              1);
    EXPECT_EQ(run(glint + " convert " + in + " -o " + (dir / "x.png").string() +
                  " --view Filmmic 2>/dev/null"),
              1);
    EXPECT_EQ(run(glint + " convert " + in + " -o " + (dir / "x.png").string() +
                  " --view Filmic --ocio-config /nonexistent.ocio 2>/dev/null"),
              3);
    EXPECT_FALSE(fs::exists(dir / "x.png"));
    fs::remove_all(dir);
}

}  // namespace
