// Image comparison metrics on synthetic images with differences placed by hand.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "core/error.h"
#include "io/image_compare.h"
#include "io/image_output.h"
#include "image/image.h"

namespace fs = std::filesystem;
using glint::io::Rgb8Image;

namespace {

Rgb8Image flat(int w, int h, unsigned char v) {
    Rgb8Image img;
    img.width = w;
    img.height = h;
    img.rgb.assign(static_cast<size_t>(w) * h * 3, v);
    return img;
}

unsigned char& at(Rgb8Image& img, int x, int y, int c) {
    return img.rgb[(static_cast<size_t>(y) * img.width + x) * 3 + c];
}

fs::path temp_dir(const std::string& name) {
    fs::path dir = fs::temp_directory_path() /
                   ("glint_compare_test_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

}  // namespace

TEST(IoCompare, IdenticalImages) {
    Rgb8Image a = flat(10, 5, 77);
    glint::io::CompareResult r = glint::io::compare_images(a, a, 2);
    EXPECT_EQ(r.pixels, 50);
    EXPECT_EQ(r.within_count, 50);
    EXPECT_DOUBLE_EQ(r.within_fraction, 1.0);
    EXPECT_DOUBLE_EQ(r.rmse, 0.0);
    EXPECT_EQ(r.max_diff, 0);
}

TEST(IoCompare, CountsLargestChannelAgainstTolerance) {
    Rgb8Image a = flat(10, 10, 100);
    Rgb8Image b = a;
    at(b, 3, 7, 1) = 103;  // 3 > 2: outside
    at(b, 5, 2, 0) = 98;   // 2: inside (<= tolerance)
    at(b, 5, 2, 2) = 102;
    at(b, 9, 9, 2) = 90;  // the largest difference
    glint::io::CompareResult r = glint::io::compare_images(a, b, 2);
    EXPECT_EQ(r.within_count, 98);
    EXPECT_DOUBLE_EQ(r.within_fraction, 0.98);
    EXPECT_EQ(r.max_diff, 10);
    EXPECT_EQ(r.max_x, 9);
    EXPECT_EQ(r.max_y, 9);
    // RMSE over all 300 channel values: (9 + 4 + 4 + 100) / 300.
    EXPECT_NEAR(r.rmse, std::sqrt(117.0 / 300.0), 1e-12);
    EXPECT_EQ(glint::io::compare_images(a, b, 3).within_count, 99);
    EXPECT_EQ(glint::io::compare_images(a, b, 0).within_count, 97);
    // MAE over the same 300 values: (3 + 2 + 2 + 10) / 300.
    EXPECT_NEAR(r.mae, 17.0 / 300.0, 1e-12);
    EXPECT_EQ(glint::io::format_compare_line(r).rfind(
                  "within=0.980000 rmse=0.6245 max=10@9,9 pixels=100 mae=0.0567 ssim=", 0),
              0u)
        << glint::io::format_compare_line(r);
}

TEST(IoCompare, MaxLocationIsFirstInRowOrder) {
    Rgb8Image a = flat(4, 3, 0);
    Rgb8Image b = a;
    at(b, 2, 2, 0) = 50;
    at(b, 1, 1, 1) = 50;
    glint::io::CompareResult r = glint::io::compare_images(a, b, 2);
    EXPECT_EQ(r.max_x, 1);
    EXPECT_EQ(r.max_y, 1);
}

TEST(IoCompare, SizeMismatchIsAnError) {
    try {
        glint::io::compare_images(flat(4, 3, 0), flat(3, 4, 0), 2);
        FAIL();
    } catch (const glint::Error& e) {
        EXPECT_NE(std::string(e.what()).find("4x3 vs 3x4"), std::string::npos) << e.what();
    }
}

TEST(IoCompare, DifferenceImageScalesToItsMaximum) {
    Rgb8Image a = flat(2, 1, 10);
    Rgb8Image b = a;
    at(b, 0, 0, 0) = 14;  // 4 -> 255
    at(b, 1, 0, 2) = 12;  // 2 -> 128 (rounded)
    Rgb8Image d = glint::io::difference_image(a, b);
    EXPECT_EQ(at(d, 0, 0, 0), 255);
    EXPECT_EQ(at(d, 1, 0, 2), 128);
    EXPECT_EQ(at(d, 0, 0, 1), 0);
    Rgb8Image zero = glint::io::difference_image(a, a);
    for (unsigned char v : zero.rgb) EXPECT_EQ(v, 0);
}

TEST(IoCompare, ReadsPngExactlyAndExrThroughSrgb) {
    fs::path dir = temp_dir("read");
    Rgb8Image a = flat(3, 2, 0);
    for (size_t i = 0; i < a.rgb.size(); ++i) a.rgb[i] = static_cast<unsigned char>(i * 13);
    std::string png = (dir / "a.png").string();
    glint::io::write_rgb8_png(a, png);
    Rgb8Image back = glint::io::read_rgb8(png);
    EXPECT_EQ(back.width, 3);
    EXPECT_EQ(back.height, 2);
    EXPECT_EQ(back.rgb, a.rgb);

    glint::Image film;
    film.width = 1;
    film.height = 1;
    film.rgba = {0.5f, 0.0f, 1.0f, 1.0f};
    std::string exr = (dir / "b.exr").string();
    glint::io::write_image(film, exr, glint::io::OutputEncoding{});
    Rgb8Image e = glint::io::read_rgb8(exr);
    ASSERT_EQ(e.rgb.size(), 3u);
    EXPECT_EQ(e.rgb[0], 188);  // sRGB(0.5), as POV-Ray writes it
    EXPECT_EQ(e.rgb[1], 0);
    EXPECT_EQ(e.rgb[2], 255);
    fs::remove_all(dir);
}

TEST(IoCompare, MissingFileIsReported) {
    try {
        glint::io::read_rgb8("/nonexistent/glint/x.png");
        FAIL();
    } catch (const glint::Error& e) {
        EXPECT_EQ(e.kind(), glint::ErrorKind::MissingFile);
    }
}

TEST(IoCompare, SsimOfIdenticalImagesIsOne) {
    Rgb8Image a = flat(40, 30, 0);
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x) at(a, x, y, (x + y) % 3) = static_cast<unsigned char>(x * 6);
    EXPECT_DOUBLE_EQ(glint::io::compute_ssim(a, a), 1.0);
    EXPECT_DOUBLE_EQ(glint::io::compare_images(a, a, 2).ssim, 1.0);
}

TEST(IoCompare, SsimOfFlatImagesIsTheLuminanceTerm) {
    // Flat images have no variance: SSIM reduces to (2 mu_a mu_b + C1) / (mu_a^2 + mu_b^2 + C1)
    // in every window.
    const double c1 = (0.01 * 255) * (0.01 * 255);
    const double expected = (2 * 100.0 * 110.0 + c1) / (100.0 * 100.0 + 110.0 * 110.0 + c1);
    EXPECT_NEAR(glint::io::compute_ssim(flat(20, 20, 100), flat(20, 20, 110)), expected, 1e-9);
    // Smaller than the 11x11 window: the window shrinks to the image.
    EXPECT_NEAR(glint::io::compute_ssim(flat(5, 3, 100), flat(5, 3, 110)), expected, 1e-9);
}

TEST(IoCompare, SsimFallsWithStructureNotWithSmallNoise) {
    // A vertical edge against the same edge moved by 4 pixels, and against the edge with
    // +-1 noise: the moved edge loses structure, the noise barely does.
    Rgb8Image a = flat(32, 32, 40);
    for (int y = 0; y < 32; ++y)
        for (int x = 16; x < 32; ++x)
            for (int c = 0; c < 3; ++c) at(a, x, y, c) = 200;
    Rgb8Image moved = flat(32, 32, 40);
    for (int y = 0; y < 32; ++y)
        for (int x = 20; x < 32; ++x)
            for (int c = 0; c < 3; ++c) at(moved, x, y, c) = 200;
    Rgb8Image noisy = a;
    for (size_t i = 0; i < noisy.rgb.size(); ++i) noisy.rgb[i] += (i % 2 ? 1 : -1);
    const double s_moved = glint::io::compute_ssim(a, moved);
    const double s_noisy = glint::io::compute_ssim(a, noisy);
    EXPECT_LT(s_moved, 0.9);
    EXPECT_GT(s_noisy, 0.99);
    EXPECT_LT(s_noisy, 1.0);
    EXPECT_DOUBLE_EQ(glint::io::compute_ssim(moved, a), s_moved);  // symmetric
}
