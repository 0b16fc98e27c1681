// Comparing two images the way the golden tests judge agreement with POV-Ray (VALIDATION.md):
// in 8-bit output space, the fraction of pixels whose largest channel difference is within a
// tolerance, plus RMSE and the largest difference with its location. Used by `glint compare`.
#pragma once

#include <string>
#include <vector>

namespace glint::io {

// An image as 8-bit RGB code values, top row first.
struct Rgb8Image {
    int width = 0;
    int height = 0;
    std::vector<unsigned char> rgb;  // width * height * 3
};

struct CompareResult {
    long long pixels = 0;        // pixels compared (width * height)
    long long within_count = 0;  // pixels whose largest channel difference <= tolerance
    double within_fraction = 0;  // within_count / pixels (1 for an empty image)
    double rmse = 0;             // over all RGB channels, in 8-bit code values
    int max_diff = 0;            // largest channel difference, in 8-bit code values
    int max_x = 0, max_y = 0;    // the first pixel (row-major) where max_diff occurs
};

// Reads an image file as 8-bit RGB. Integer files are rescaled to 8 bits by OpenImageIO
// (16-bit v -> round(v * 255 / 65535)); float files (exr, hdr) are sRGB-encoded and quantized
// as glint writes PNG. Gray images are spread to RGB; alpha is ignored. Throws
// Error(MissingFile) when the file cannot be opened or read.
Rgb8Image read_rgb8(const std::string& path);

// Throws Error(Usage) when the sizes differ (naming both sizes).
CompareResult compare_images(const Rgb8Image& a, const Rgb8Image& b, double tolerance);

// |a - b| per channel, scaled so the largest difference becomes 255 (all black when the
// images are equal); what `glint compare --diff` writes as PNG.
Rgb8Image difference_image(const Rgb8Image& a, const Rgb8Image& b);

// Writes 8-bit RGB as PNG (atomically, like write_image). Throws Error(Output).
void write_rgb8_png(const Rgb8Image& image, const std::string& path);

// The contract line: `within=<fraction> rmse=<x> max=<d>@<x>,<y> pixels=<n>`.
std::string format_compare_line(const CompareResult& r);

}  // namespace glint::io
