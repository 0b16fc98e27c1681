// height_field from a function (`function W, H { ... }`) and from a Fractint .pot file: the
// 16-bit heights POV-Ray 3.7 builds from them (parstxtr.cpp's function image, gif.cpp's pot
// halves) and where they land on the grid.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>
#include <vector>

#include "geom_test_util.h"
#include "image/gif_indices.h"
#include "pov_test_util.h"
#include "render/render.h"

namespace glint {
namespace {

const scene::HeightField& only_height_field(const scene::Scene& sc) {
    EXPECT_EQ(sc.objects.size(), 1u);
    return std::get<scene::HeightField>(sc.objects.at(0).shape);
}

// Heights at (column, row z) of the grid.
uint16_t at(const scene::HeightField& h, int x, int z) {
    return h.heights.at(static_cast<size_t>(z) * h.grid_w + x);
}

TEST(HeightFieldFunction, GridAlongX) {
    auto sc = pov::testing::parse("height_field { function 3, 3 { x } smooth }");
    const auto& h = only_height_field(sc);
    ASSERT_EQ(h.grid_w, 3);
    ASSERT_EQ(h.grid_h, 3);
    EXPECT_TRUE(h.smooth);
    for (int z = 0; z < 3; ++z) {
        EXPECT_EQ(at(h, 0, z), 0);
        // 0.5 * 65535 truncated into the 16-bit image, then scaled back in float.
        EXPECT_EQ(at(h, 1, z), 32767);
        EXPECT_EQ(at(h, 2, z), 65535);
    }
}

TEST(HeightFieldFunction, FunctionRowZeroLiesAtZOne) {
    // POV-Ray's image row i is the function at y = i / (H - 1); row 0 is the image's top, z = 1.
    auto sc = pov::testing::parse("height_field { function 2, 3 { y } }");
    const auto& h = only_height_field(sc);
    ASSERT_EQ(h.grid_w, 2);
    ASSERT_EQ(h.grid_h, 3);
    EXPECT_EQ(at(h, 0, 0), 65535);
    EXPECT_EQ(at(h, 1, 1), 32767);
    EXPECT_EQ(at(h, 0, 2), 0);
}

TEST(HeightFieldFunction, OutOfRangeValuesWrapAsInPovRay) {
    // No clamping: the float goes into the 16-bit image through a 32-bit integer.
    auto sc = pov::testing::parse("height_field { function 2, 2 { 1.5 } }");
    EXPECT_EQ(at(only_height_field(sc), 0, 0), 32766);
    sc = pov::testing::parse("height_field { function 2, 2 { -0.25 } }");
    EXPECT_EQ(at(only_height_field(sc), 1, 1), 49153);
    sc = pov::testing::parse("height_field { function 2.4, 2.6 { 0.3 } }");  // rounded sizes
    EXPECT_EQ(only_height_field(sc).grid_w, 2);
    EXPECT_EQ(only_height_field(sc).grid_h, 3);
    EXPECT_EQ(at(only_height_field(sc), 0, 0), 19660);
}

TEST(HeightFieldFunction, PigmentGreyIsTheHeight) {
    pov::ParseOptions o;
    o.pattern_hook = render::parse_time_pattern;
    auto sc = pov::testing::parse(
        "height_field { function 2, 2 { pigment { color rgb <1, 0, 0> } } }", o);
    EXPECT_EQ(at(only_height_field(sc), 0, 0), 19463);  // 0.297 red
    // Without the hook the pigment cannot be evaluated: the object is left out.
    sc = pov::testing::parse("height_field { function 2, 2 { pigment { rgb 1 } } }");
    EXPECT_TRUE(sc.objects.empty());
}

TEST(HeightFieldFunction, Errors) {
    using pov::testing::error_of;
    EXPECT_EQ(error_of("height_field { function 1, 5 { x } }"),
              "1:25: height_field function size must be at least 2 x 2 and at most 2^26 points");
    EXPECT_EQ(error_of("height_field { function 3, 3 { transform { scale 2 } } }"),
              "1:25: unsupported function type in a height_field function (a pigment or a "
              "scalar function is needed)");
}

// A GIF of palette indices whose LZW stream restarts (clear code) before each pixel, so every
// code is 9 bits wide.
void write_gif(const std::string& path, int w, int h, const std::vector<uint8_t>& idx) {
    std::vector<uint8_t> d = {'G', 'I', 'F', '8', '7', 'a', uint8_t(w), uint8_t(w >> 8),
                              uint8_t(h), uint8_t(h >> 8), 0xF7, 0, 0};
    for (int i = 0; i < 256; ++i) d.insert(d.end(), {0, 0, 0});  // every colour the same
    d.insert(d.end(), {',', 0, 0, 0, 0, uint8_t(w), uint8_t(w >> 8), uint8_t(h),
                       uint8_t(h >> 8), 0, 8});
    std::vector<uint8_t> bytes;
    uint32_t acc = 0;
    int nbits = 0;
    auto put = [&](int code) {
        acc |= static_cast<uint32_t>(code) << nbits;
        for (nbits += 9; nbits >= 8; nbits -= 8, acc >>= 8) bytes.push_back(uint8_t(acc));
    };
    for (uint8_t v : idx) put(256), put(v);
    put(257);
    if (nbits > 0) bytes.push_back(uint8_t(acc));
    for (size_t i = 0; i < bytes.size(); i += 255) {
        size_t n = std::min<size_t>(255, bytes.size() - i);
        d.push_back(uint8_t(n));
        d.insert(d.end(), bytes.begin() + i, bytes.begin() + i + n);
    }
    d.insert(d.end(), {0, ';'});
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(d.data()),
                                                static_cast<std::streamsize>(d.size()));
}

TEST(HeightFieldPot, HalvesAreHighAndLowBytes) {
    auto dir = std::filesystem::temp_directory_path() /
               ("glint_hf_pot_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "t.pot").string();
    // 4 x 2 GIF -> 2 x 2 heights. Top row: 0x1234, 0x0000; bottom row: 0x8000, 0xFFFF.
    write_gif(path, 4, 2, {0x12, 0x00, 0x34, 0x00, 0x80, 0xFF, 0x00, 0xFF});
    GifIndices gif;
    std::string err;
    ASSERT_TRUE(read_gif_indices(path, &gif, &err)) << err;
    EXPECT_EQ(gif.width, 4);
    EXPECT_EQ(gif.index[2], 0x34);
    EXPECT_EQ(gif.index[5], 0xFF);

    auto sc = pov::testing::parse("height_field { pot \"" + path + "\" }");
    const auto& hf = only_height_field(sc);
    EXPECT_TRUE(hf.pot);
    auto g = test::build_one(hf);
    render::Hit hit;
    // Object space: x, z in [0, 1]; the image's bottom row at z = 0; height / 65536.
    auto down = [&](double x, double z) {
        EXPECT_TRUE(g->intersect(test::ray({x, 2, z}, {0, -1, 0}), &hit));
        return hit.p.y * 65536;
    };
    // Near the corners (the heights there differ by thousands).
    EXPECT_NEAR(down(0.001, 0.001), 0x8000, 100);
    EXPECT_NEAR(down(0.999, 0.001), 0xFFFF, 100);
    EXPECT_NEAR(down(0.001, 0.999), 0x1234, 100);
    EXPECT_NEAR(down(0.999, 0.999), 0, 100);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace glint
