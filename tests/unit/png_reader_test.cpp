// glint's own PNG reader (image/png_reader.h) against OpenImageIO's on the same files: every
// colour type and bit depth PNG has, palettes with and without transparency, interlacing, and
// the gamma chunks. Image maps and height fields see the header and pixels of one where they
// saw the other's, so both must agree to the bit.
#include "image/png_reader.h"

#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "image/image_library.h"

namespace glint {
namespace {

struct Variant {
    std::string name;
    int depth;
    int color_type;
    bool trns = false;
    bool interlaced = false;
    double file_gamma = 0;  // gAMA chunk value; 0: none
    bool srgb = false;
};

int samples_per_pixel(int color_type) {
    switch (color_type) {
        case PNG_COLOR_TYPE_GRAY:
            return 1;
        case PNG_COLOR_TYPE_GRAY_ALPHA:
            return 2;
        case PNG_COLOR_TYPE_RGB:
            return 3;
        case PNG_COLOR_TYPE_RGB_ALPHA:
            return 4;
        default:
            return 1;  // palette index
    }
}

// Writes `v` as a 7x5 PNG of random samples; returns false when libpng fails.
bool write_variant(const Variant& v, const std::string& path) {
    constexpr int w = 7, h = 5;
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        std::fclose(f);
        return false;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, w, h, v.depth, v.color_type,
                 v.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    std::mt19937 rng(static_cast<unsigned>(v.depth * 31 + v.color_type * 7 + v.trns));
    const int entries = 1 << std::min(v.depth, 8);
    std::vector<png_color> palette(static_cast<size_t>(entries));
    std::vector<png_byte> alphas(static_cast<size_t>(entries));
    if (v.color_type == PNG_COLOR_TYPE_PALETTE) {
        for (int i = 0; i < entries; ++i) {
            palette[i] = {static_cast<png_byte>(rng()), static_cast<png_byte>(rng()),
                          static_cast<png_byte>(rng())};
            alphas[i] = static_cast<png_byte>(rng());
        }
        png_set_PLTE(png, info, palette.data(), entries);
        if (v.trns) png_set_tRNS(png, info, alphas.data(), entries, nullptr);
    } else if (v.trns) {
        png_color_16 key{};
        key.gray = key.red = static_cast<png_uint_16>(rng() & ((1 << v.depth) - 1));
        key.green = key.blue = 0;
        png_set_tRNS(png, info, nullptr, 0, &key);
    }
    if (v.srgb) png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    if (v.file_gamma > 0) png_set_gAMA(png, info, v.file_gamma);
    png_write_info(png, info);
    const size_t row_bytes =
        (static_cast<size_t>(w) * samples_per_pixel(v.color_type) * v.depth + 7) / 8;
    std::vector<png_byte> pixels(row_bytes * h);
    for (auto& b : pixels) b = static_cast<png_byte>(rng());
    if (v.color_type == PNG_COLOR_TYPE_PALETTE && v.depth == 8)
        for (auto& b : pixels) b = static_cast<png_byte>(b % entries);
    std::vector<png_bytep> rows(h);
    for (int y = 0; y < h; ++y) rows[y] = pixels.data() + y * row_bytes;
    png_write_image(png, rows.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
    return true;
}

std::vector<Variant> variants() {
    std::vector<Variant> out;
    for (int d : {1, 2, 4, 8, 16}) {
        out.push_back({"gray" + std::to_string(d), d, PNG_COLOR_TYPE_GRAY});
        out.push_back({"gray" + std::to_string(d) + "_trns", d, PNG_COLOR_TYPE_GRAY, true});
    }
    for (int d : {8, 16}) {
        out.push_back({"gray_alpha" + std::to_string(d), d, PNG_COLOR_TYPE_GRAY_ALPHA});
        out.push_back({"rgb" + std::to_string(d), d, PNG_COLOR_TYPE_RGB});
        out.push_back({"rgb" + std::to_string(d) + "_trns", d, PNG_COLOR_TYPE_RGB, true});
        out.push_back({"rgba" + std::to_string(d), d, PNG_COLOR_TYPE_RGB_ALPHA});
    }
    for (int d : {1, 2, 4, 8}) {
        out.push_back({"palette" + std::to_string(d), d, PNG_COLOR_TYPE_PALETTE});
        out.push_back({"palette" + std::to_string(d) + "_trns", d, PNG_COLOR_TYPE_PALETTE, true});
    }
    out.push_back({"rgb8_interlaced", 8, PNG_COLOR_TYPE_RGB, false, true});
    out.push_back({"rgba16_interlaced", 16, PNG_COLOR_TYPE_RGB_ALPHA, false, true});
    out.push_back({"rgb8_gamma22", 8, PNG_COLOR_TYPE_RGB, false, false, 1 / 2.2});
    out.push_back({"rgb8_gamma18", 8, PNG_COLOR_TYPE_RGB, false, false, 1 / 1.8});
    out.push_back({"rgb8_gamma245", 8, PNG_COLOR_TYPE_RGB, false, false, 1 / 2.45});
    out.push_back({"rgb8_gamma1", 8, PNG_COLOR_TYPE_RGB, false, false, 1.0});
    out.push_back({"gray16_gamma1", 16, PNG_COLOR_TYPE_GRAY, false, false, 1.0});
    out.push_back({"rgb8_srgb", 8, PNG_COLOR_TYPE_RGB, false, false, 0, true});
    out.push_back({"rgb8_srgb_gamma", 8, PNG_COLOR_TYPE_RGB, false, false, 1 / 2.2, true});
    return out;
}

class PngReader : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() /
               ("glint_png_reader_" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    std::filesystem::path dir_;
};

TEST_F(PngReader, GivesWhatOpenImageIoGivesForEveryKindOfPng) {
    const std::vector<std::pair<std::string, int>> unassociated = {{"oiio:UnassociatedAlpha", 1}};
    for (const Variant& v : variants()) {
        SCOPED_TRACE(v.name);
        const std::string path = (dir_ / (v.name + ".png")).string();
        ASSERT_TRUE(write_variant(v, path));
        std::string why;
        std::unique_ptr<ImageReader> ours = open_png(path, true, &why);
        ASSERT_TRUE(ours) << why;
        std::unique_ptr<ImageReader> theirs = image_library().open(path, unassociated, &why);
        ASSERT_TRUE(theirs) << why;
        const ImageHeader& a = ours->header();
        const ImageHeader& b = theirs->header();
        EXPECT_EQ(a.width, b.width);
        EXPECT_EQ(a.height, b.height);
        ASSERT_EQ(a.channels, b.channels);
        EXPECT_EQ(a.type, b.type);
        EXPECT_EQ(a.alpha_channel, b.alpha_channel);
        EXPECT_EQ(a.format, b.format);
        EXPECT_EQ(a.colorspace, b.colorspace);
        EXPECT_EQ(a.gamma, b.gamma);
        const size_t n = static_cast<size_t>(a.width) * a.height * a.channels;
        std::vector<float> pa(n, -1.0f), pb(n, -2.0f);
        ASSERT_EQ(ours->read(a.channels, pa.data()), "");
        ASSERT_EQ(theirs->read(b.channels, pb.data()), "");
        size_t differ = 0;
        for (size_t i = 0; i < n; ++i) differ += pa[i] != pb[i];
        EXPECT_EQ(differ, 0u) << "of " << n << " samples";
    }
}

TEST_F(PngReader, FewerChannelsThanTheFileHasTakesTheFirstOnes) {
    const Variant v{"rgba8", 8, PNG_COLOR_TYPE_RGB_ALPHA};
    const std::string path = (dir_ / "rgba8.png").string();
    ASSERT_TRUE(write_variant(v, path));
    std::string why;
    auto all = open_png(path, true, &why);
    auto one = open_png(path, true, &why);
    ASSERT_TRUE(all && one);
    std::vector<float> pa(7 * 5 * 4), pb(7 * 5);
    ASSERT_EQ(all->read(4, pa.data()), "");
    ASSERT_EQ(one->read(1, pb.data()), "");
    for (size_t i = 0; i < pb.size(); ++i) EXPECT_EQ(pb[i], pa[4 * i]);
}

TEST_F(PngReader, AssociatedAlphaAndOtherFormatsAreLeftToOpenImageIo) {
    const std::string rgba = (dir_ / "rgba.png").string();
    ASSERT_TRUE(write_variant({"rgba8", 8, PNG_COLOR_TYPE_RGB_ALPHA}, rgba));
    std::string why = "unchanged";
    EXPECT_FALSE(open_png(rgba, false, &why));
    EXPECT_EQ(why, "");
    const std::string rgb = (dir_ / "rgb.png").string();
    ASSERT_TRUE(write_variant({"rgb8", 8, PNG_COLOR_TYPE_RGB}, rgb));
    EXPECT_TRUE(open_png(rgb, false, &why)) << "no alpha: nothing to associate";
    const std::string text = (dir_ / "not_a.png").string();
    std::FILE* f = std::fopen(text.c_str(), "wb");
    ASSERT_TRUE(f);
    std::fputs("this is not an image\n", f);
    std::fclose(f);
    EXPECT_FALSE(open_png(text, true, &why));
    EXPECT_EQ(why, "");
    EXPECT_FALSE(open_png((dir_ / "missing.png").string(), true, &why));
    EXPECT_EQ(why, "");
}

TEST_F(PngReader, ABrokenHeaderIsAnErrorOfItsOwn) {
    const std::string good = (dir_ / "good.png").string();
    ASSERT_TRUE(write_variant({"rgb8", 8, PNG_COLOR_TYPE_RGB}, good));
    std::FILE* in = std::fopen(good.c_str(), "rb");
    ASSERT_TRUE(in);
    std::vector<unsigned char> bytes(20);  // the signature and part of IHDR
    ASSERT_EQ(std::fread(bytes.data(), 1, bytes.size(), in), bytes.size());
    std::fclose(in);
    const std::string cut = (dir_ / "cut.png").string();
    std::FILE* out = std::fopen(cut.c_str(), "wb");
    ASSERT_TRUE(out);
    std::fwrite(bytes.data(), 1, bytes.size(), out);
    std::fclose(out);
    std::string why;
    EXPECT_FALSE(open_png(cut, true, &why));
    EXPECT_EQ(why, "Read error: hit end of file");
}

// What the reader is for: a scene whose only image is a PNG map renders without opening
// OpenImageIO's module (LD_DEBUG=files lists each library the loader opens, dlopen included).
TEST_F(PngReader, ASceneWithAPngImageMapDoesNotLoadOpenImageIo) {
    ASSERT_TRUE(write_variant({"rgba8", 8, PNG_COLOR_TYPE_RGB_ALPHA}, (dir_ / "tex.png").string()));
    {
        std::FILE* f = std::fopen((dir_ / "s.pov").c_str(), "w");
        ASSERT_TRUE(f);
        std::fputs(
            "camera { location <0, 0, -3> look_at 0 }\n"
            "light_source { <2, 4, -3> color rgb 1 }\n"
            "box { -1, 1 pigment { image_map { png \"tex.png\" } } }\n",
            f);
        std::fclose(f);
    }
    const std::string log = (dir_ / "ld.txt").string();
    const std::string cmd =
        "cd '" + dir_.string() + "' && LD_DEBUG=files '" + std::string(GLINT_BINARY) +
        "' render s.pov -o out.png --width 8 --height 8 > /dev/null 2> '" + log + "'";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    EXPECT_TRUE(std::filesystem::exists(dir_ / "out.png"));
    std::FILE* f = std::fopen(log.c_str(), "r");
    ASSERT_TRUE(f);
    std::string opened;
    char buf[4096];
    while (size_t n = std::fread(buf, 1, sizeof buf, f)) opened.append(buf, n);
    std::fclose(f);
    EXPECT_NE(opened.find("libpng16"), std::string::npos) << opened;
    EXPECT_EQ(opened.find("libglint_oiio"), std::string::npos);
    EXPECT_EQ(opened.find("libOpenImageIO"), std::string::npos);
}

}  // namespace
}  // namespace glint
