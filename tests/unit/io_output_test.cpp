// Image output: round trips through every format, the encoding values POV-Ray 3.7 writes
// (measured with the installed povray, see docs/output-encoding.md), and the atomic write.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "io/color_encoding.h"
#include "io/image_output.h"
#include "io/scene_encoding.h"
#include "image/image.h"
#include "scene/scene.h"

namespace fs = std::filesystem;
using glint::io::OutputEncoding;

namespace {

fs::path temp_dir(const std::string& name) {
    fs::path dir =
        fs::temp_directory_path() / ("glint_io_test_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

glint::Image ramp(int w, int h) {
    glint::Image img;
    img.width = w;
    img.height = h;
    img.rgba.resize(static_cast<size_t>(w) * h * 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = img.pixel(x, y);
            p[0] = x / float(w - 1);
            p[1] = y / float(h - 1);
            p[2] = 0.25f + 0.5f * ((x + y) % 2);
            p[3] = 1.0f;
        }
    return img;
}

std::vector<float> read_float(const std::string& path, int* w, int* h, int* channels,
                              OIIO::TypeDesc* format = nullptr) {
    auto in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << OIIO::geterror();
    if (!in) return {};
    const OIIO::ImageSpec& spec = in->spec();
    *w = spec.width;
    *h = spec.height;
    *channels = spec.nchannels;
    if (format) *format = spec.format;
    std::vector<float> data(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, data.data()));
    return data;
}

std::vector<int> read_codes(const std::string& path, OIIO::TypeDesc type, int max) {
    auto in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << OIIO::geterror();
    if (!in) return {};
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<float> data(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    EXPECT_EQ(spec.format, type);
    EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, data.data()));
    std::vector<int> codes;
    for (float v : data) codes.push_back(static_cast<int>(std::lround(v * max)));
    return codes;
}

OutputEncoding linear() {
    OutputEncoding e;
    e.transfer = OutputEncoding::Transfer::Linear;
    return e;
}

int code8(float v, const OutputEncoding& e) {
    return static_cast<int>(glint::io::quantize(glint::io::encode_value(v, e), 255));
}

}  // namespace

// POV-Ray 3.7.0 (Debian 12), a flat `rgb v` plane with ambient 1 diffuse 0, read back from
// its PNG. The three columns: `#version 3.7; assumed_gamma 1.0`, `#version 3.7;
// assumed_gamma 2.2`, and `#version 3.6;` without assumed_gamma.
struct PovMeasurement {
    float value;
    int gamma1;
    int gamma22;
    int legacy;
};
constexpr PovMeasurement kPovPng[] = {
    {0.1f, 89, 19, 26},    {0.2f, 124, 48, 51},    {0.25f, 137, 61, 64},
    {0.5f, 188, 128, 128}, {0.75f, 225, 193, 191}, {0.9f, 243, 230, 230},
};

TEST(IoEncoding, MatchesPovRayPngValues) {
    glint::scene::Scene g1, g22, legacy;
    g1.version = 3.7;
    g1.global.assumed_gamma = 1.0;
    g22.version = 3.7;
    g22.global.assumed_gamma = 2.2;
    legacy.version = 3.6;
    for (const PovMeasurement& m : kPovPng) {
        EXPECT_EQ(code8(m.value, glint::io::output_encoding_for(g1)), m.gamma1) << m.value;
        EXPECT_EQ(code8(m.value, glint::io::output_encoding_for(g22)), m.gamma22) << m.value;
        EXPECT_EQ(code8(m.value, glint::io::output_encoding_for(legacy)), m.legacy) << m.value;
    }
}

TEST(IoEncoding, SceneRules) {
    glint::scene::Scene s;
    s.version = 3.7;  // no assumed_gamma: POV-Ray 3.7 implies 1.0
    OutputEncoding e = glint::io::output_encoding_for(s);
    EXPECT_EQ(e.transfer, OutputEncoding::Transfer::Srgb);
    EXPECT_DOUBLE_EQ(e.working_gamma, 1.0);
    EXPECT_FALSE(e.working_srgb);
    s.version = 3.62;  // what POV-Ray assumes without #version
    e = glint::io::output_encoding_for(s);
    EXPECT_TRUE(e.working_srgb);  // working space = file space = display gamma
    EXPECT_EQ(e.transfer, OutputEncoding::Transfer::Srgb);
    s.global.assumed_gamma = 1.8;  // assumed_gamma turns gamma handling on in any version
    e = glint::io::output_encoding_for(s);
    EXPECT_EQ(e.transfer, OutputEncoding::Transfer::Srgb);
    EXPECT_FALSE(e.working_srgb);
    EXPECT_DOUBLE_EQ(e.working_gamma, 1.8);
}

// POV-Ray 3.7.0's EXR (+FE) of the same flat rgb 0.5 plane: float formats get linear light,
// the working space decoded. POV-Ray writes half floats (0.217651, 0.213989); glint writes
// 32-bit floats, so it must match the exact decoding closely and POV-Ray's within a half ulp.
TEST(IoEncoding, ExrGetsLinearLightLikePovRay) {
    struct Case {
        double version;
        std::optional<double> assumed_gamma;
        double exact;  // 0.5^2.2; sRGB decoding of 0.5 (IEC 61966-2-1)
        float pov;
    } cases[] = {{3.7, 1.0, 0.5, 0.5f},
                 {3.7, 2.2, std::pow(0.5, 2.2), 0.217651f},
                 {3.6, std::nullopt, std::pow((0.5 + 0.055) / 1.055, 2.4), 0.213989f}};
    fs::path dir = temp_dir("exr_encoding");
    for (const Case& c : cases) {
        glint::scene::Scene s;
        s.version = c.version;
        s.global.assumed_gamma = c.assumed_gamma;
        glint::Image img;
        img.width = 2;
        img.height = 1;
        img.rgba = {0.5f, 0.5f, 0.5f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f};
        std::string path = (dir / "a.exr").string();
        glint::io::write_image(img, path, glint::io::output_encoding_for(s));
        int w, h, ch;
        std::vector<float> data = read_float(path, &w, &h, &ch);
        ASSERT_EQ(data.size(), 6u);
        EXPECT_NEAR(data[0], c.exact, 2e-6) << c.version;
        EXPECT_NEAR(data[0], c.pov, 1e-4) << c.version;
        EXPECT_EQ(data[3], 0.0f);
    }
    fs::remove_all(dir);
}

TEST(IoEncoding, ClampsAndQuantizesLikePovRay) {
    OutputEncoding srgb;
    EXPECT_EQ(code8(-1.0f, srgb), 0);
    EXPECT_EQ(code8(NAN, srgb), 0);
    EXPECT_EQ(code8(INFINITY, srgb), 255);
    EXPECT_EQ(code8(7.0f, srgb), 255);
    EXPECT_EQ(code8(1.0f, srgb), 255);
    // Rounding, not truncation: 0.5/255 above a code rounds up.
    EXPECT_EQ(glint::io::quantize(100.5f / 255.0f, 255), 101u);
    EXPECT_EQ(glint::io::quantize(100.49f / 255.0f, 255), 100u);
    EXPECT_EQ(glint::io::quantize(1.0f, 65535), 65535u);
    OutputEncoding g;
    g.transfer = OutputEncoding::Transfer::Gamma;
    g.gamma = 2.0;
    EXPECT_EQ(code8(0.25f, g), 128);  // 0.25^(1/2) = 0.5 -> 127.5 -> 128
}

TEST(IoOutput, PngRoundTripIsExact) {
    fs::path dir = temp_dir("png");
    glint::Image img = ramp(17, 9);
    std::string path = (dir / "a.png").string();
    glint::io::write_image(img, path, linear());
    std::vector<int> codes = read_codes(path, OIIO::TypeDesc::UINT8, 255);
    ASSERT_EQ(codes.size(), size_t(17 * 9 * 3));
    for (size_t i = 0; i < codes.size(); ++i)
        ASSERT_EQ(codes[i], std::lround(std::floor(img.rgba[i / 3 * 4 + i % 3] * 255 + 0.5f)));
    fs::remove_all(dir);
}

// The libraries the dynamic loader opened while glint rendered a one-sphere scene to `output`
// (LD_DEBUG=files lists each one it opens, at start-up and by dlopen).
std::string libraries_opened_for(const fs::path& dir, const std::string& output) {
    {
        std::ofstream scene(dir / "s.pov");
        scene << "camera { location <0, 0, -3> look_at 0 }\n"
                 "light_source { <2, 4, -3> color rgb 1 }\n"
                 "sphere { 0, 1 pigment { rgb 1 } }\n";
    }
    const std::string log = (dir / "ld.txt").string();
    const std::string cmd = "LD_DEBUG=files '" + std::string(GLINT_BINARY) + "' render '" +
                            (dir / "s.pov").string() + "' -o '" + (dir / output).string() +
                            "' --width 8 --height 8 > /dev/null 2> '" + log + "'";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::ifstream in(log);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// A PNG without alpha is libpng's (image/png_writer.h): a render that writes one never opens
// OpenImageIO's module nor OpenImageIO; an EXR does (the check can see a load).
TEST(IoOutput, PlainPngDoesNotLoadOpenImageIo) {
    fs::path dir = temp_dir("plainpng");
    const std::string png = libraries_opened_for(dir, "a.png");
    EXPECT_TRUE(fs::exists(dir / "a.png"));
    EXPECT_NE(png.find("libpng16"), std::string::npos) << png;
    EXPECT_EQ(png.find("libglint_oiio"), std::string::npos);
    EXPECT_EQ(png.find("libOpenImageIO"), std::string::npos);
    const std::string exr = libraries_opened_for(dir, "a.exr");
    EXPECT_TRUE(fs::exists(dir / "a.exr"));
    EXPECT_NE(exr.find("libglint_oiio"), std::string::npos);
    EXPECT_NE(exr.find("libOpenImageIO"), std::string::npos);
    fs::remove_all(dir);
}

// OpenImageIO reads back the colour space, the gamma and the text that libpng was given.
TEST(IoOutput, PlainPngCarriesColorSpaceAndText) {
    fs::path dir = temp_dir("pngtext");
    glint::Image img = ramp(5, 3);
    const std::string a = (dir / "a.png").string(), g = (dir / "g.png").string();
    glint::io::write_image(img, a, OutputEncoding(),
                           {{"ImageDescription", "a ramp"}, {"glint:partial", "tiles 1/2"}});
    OutputEncoding gamma;
    gamma.transfer = OutputEncoding::Transfer::Gamma;
    gamma.gamma = 2.0;
    glint::io::write_image(img, g, gamma);

    auto in = OIIO::ImageInput::open(a);
    ASSERT_TRUE(in) << OIIO::geterror();
    EXPECT_EQ(in->spec().get_string_attribute("oiio:ColorSpace"), "sRGB");
    EXPECT_EQ(in->spec().get_string_attribute("ImageDescription"), "a ramp");
    EXPECT_EQ(in->spec().get_string_attribute("glint:partial"), "tiles 1/2");
    in->close();
    in = OIIO::ImageInput::open(g);
    ASSERT_TRUE(in) << OIIO::geterror();
    EXPECT_NEAR(in->spec().get_float_attribute("oiio:Gamma"), 2.0f, 1e-3);
    in->close();
    fs::remove_all(dir);
}

TEST(IoOutput, PngWithAlphaKeepsCoverage) {
    fs::path dir = temp_dir("alpha");
    glint::Image img = ramp(4, 4);
    img.pixel(1, 1)[3] = 0.5f;
    OutputEncoding e;
    e.alpha = true;
    std::string path = (dir / "a.png").string();
    glint::io::write_image(img, path, e);
    int w, h, c;
    std::vector<float> data = read_float(path, &w, &h, &c);
    ASSERT_EQ(c, 4);
    EXPECT_NEAR(data[(1 * 4 + 1) * 4 + 3], 128 / 255.0f, 1e-6);
    EXPECT_NEAR(data[3], 1.0f, 1e-6);
    fs::remove_all(dir);
}

TEST(IoOutput, TiffIsSixteenBit) {
    fs::path dir = temp_dir("tif");
    glint::Image img = ramp(8, 8);
    std::string path = (dir / "a.tif").string();
    glint::io::write_image(img, path, linear());
    std::vector<int> codes = read_codes(path, OIIO::TypeDesc::UINT16, 65535);
    ASSERT_EQ(codes.size(), size_t(8 * 8 * 3));
    for (size_t i = 0; i < codes.size(); ++i)
        ASSERT_EQ(codes[i], std::lround(std::floor(img.rgba[i / 3 * 4 + i % 3] * 65535 + 0.5f)));
    fs::remove_all(dir);
}

TEST(IoOutput, ExrKeepsLinearFloats) {
    fs::path dir = temp_dir("exr");
    glint::Image img = ramp(8, 6);
    img.pixel(2, 3)[0] = 17.25f;  // beyond display range: kept
    OutputEncoding srgb;          // ignored for float formats
    std::string path = (dir / "a.exr").string();
    glint::io::write_image(img, path, srgb);
    int w, h, c;
    OIIO::TypeDesc format;
    std::vector<float> data = read_float(path, &w, &h, &c, &format);
    ASSERT_EQ(w, 8);
    ASSERT_EQ(h, 6);
    ASSERT_EQ(c, 3);
    EXPECT_EQ(format, OIIO::TypeDesc::FLOAT);
    for (int i = 0; i < w * h; ++i)
        for (int k = 0; k < 3; ++k) ASSERT_EQ(data[i * 3 + k], img.rgba[i * 4 + k]);
    fs::remove_all(dir);
}

TEST(IoOutput, HdrKeepsLinearValuesWithinRgbePrecision) {
    fs::path dir = temp_dir("hdr");
    glint::Image img = ramp(8, 6);
    img.pixel(0, 0)[0] = 5.0f;
    std::string path = (dir / "a.hdr").string();
    glint::io::write_image(img, path, OutputEncoding{});
    int w, h, c;
    std::vector<float> data = read_float(path, &w, &h, &c);
    ASSERT_EQ(c, 3);
    for (int i = 0; i < w * h; ++i) {
        float largest = std::max({img.rgba[i * 4], img.rgba[i * 4 + 1], img.rgba[i * 4 + 2]});
        // RGBE shares one exponent: error up to one step of the largest channel's mantissa.
        for (int k = 0; k < 3; ++k)
            ASSERT_NEAR(data[i * 3 + k], img.rgba[i * 4 + k], largest / 128 + 1e-6);
    }
    fs::remove_all(dir);
}

TEST(IoOutput, JpegIsCloseForFlatColor) {
    fs::path dir = temp_dir("jpg");
    glint::Image img;
    img.width = 16;
    img.height = 16;
    img.rgba.assign(16 * 16 * 4, 0.5f);
    std::string path = (dir / "a.jpeg").string();
    glint::io::write_image(img, path, OutputEncoding{});
    int w, h, c;
    std::vector<float> data = read_float(path, &w, &h, &c);
    ASSERT_EQ(c, 3);
    for (float v : data) ASSERT_NEAR(v * 255, 188, 2);  // sRGB(0.5), lossy within 2 codes
    fs::remove_all(dir);
}

TEST(IoOutput, UnsupportedExtensionIsAnOutputError) {
    fs::path dir = temp_dir("ext");
    for (const char* name : {"a.bmp", "a", "a.png.txt"}) {
        try {
            glint::io::write_image(ramp(2, 2), (dir / name).string(), OutputEncoding{});
            FAIL() << name;
        } catch (const glint::Error& e) {
            EXPECT_EQ(e.kind(), glint::ErrorKind::Output);
            EXPECT_NE(std::string(e.what()).find("unsupported output format"), std::string::npos);
        }
    }
    EXPECT_TRUE(fs::is_empty(dir));
    EXPECT_EQ(glint::io::output_format_for("x/Y.PNG"), "png");
    EXPECT_EQ(glint::io::output_format_for("y.tiff"), "tiff");
    fs::remove_all(dir);
}

TEST(IoOutput, FailedWriteLeavesNoFile) {
    fs::path dir = temp_dir("fail");
    // A folder that does not exist: nothing can be created.
    std::string missing = (dir / "no" / "such" / "a.png").string();
    EXPECT_THROW(glint::io::write_image(ramp(4, 4), missing, OutputEncoding{}), glint::Error);
    EXPECT_FALSE(fs::exists(dir / "no"));
    // The target is a folder: the temporary file is written, the rename fails, and the
    // temporary must be gone afterwards.
    fs::create_directory(dir / "b.png");
    try {
        glint::io::write_image(ramp(4, 4), (dir / "b.png").string(), OutputEncoding{});
        FAIL();
    } catch (const glint::Error& e) {
        EXPECT_EQ(e.kind(), glint::ErrorKind::Output);
    }
    std::vector<fs::path> left;
    for (const auto& entry : fs::directory_iterator(dir)) left.push_back(entry.path());
    ASSERT_EQ(left.size(), 1u);
    EXPECT_EQ(left[0].filename(), "b.png");
    EXPECT_TRUE(fs::is_empty(dir / "b.png"));
    fs::remove_all(dir);
}

TEST(IoOutput, ReplacesAnExistingFile) {
    fs::path dir = temp_dir("replace");
    std::string path = (dir / "a.png").string();
    glint::io::write_image(ramp(4, 4), path, OutputEncoding{});
    glint::io::write_image(ramp(6, 5), path, OutputEncoding{});
    int w, h, c;
    read_float(path, &w, &h, &c);
    EXPECT_EQ(w, 6);
    EXPECT_EQ(h, 5);
    fs::remove_all(dir);
}
