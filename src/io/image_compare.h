// Comparing two images the way the golden tests judge agreement with POV-Ray (VALIDATION.md):
// in 8-bit output space, the fraction of pixels whose largest channel difference is within a
// tolerance, plus RMSE, mean absolute error, SSIM and the largest difference with its location.
// Used by `glint compare` and, through it, the golden tests and tests/pov_examples/compat.py.
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
    double mae = 0;              // mean absolute difference over all RGB channels, 8-bit units
    double ssim = 1;             // structural similarity of the lumas, see compute_ssim
    // On linear values (compare_linear), filled by `glint compare`:
    double relmse = 0;       // relative MSE, VALIDATION.md
    double rmse_linear = 0;  // root mean square difference of the linear RGB values
};

// An image as linear RGB floats, top row first: what the Monte Carlo metrics read.
struct LinearImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // width * height * 3
};

// Metrics of an image x against a reference r on linear values, over every RGB value:
// relMSE = mean((x - r)^2 / (r^2 + 0.01)) (VALIDATION.md; the 0.01 keeps dark pixels from
// dominating), RMSE = sqrt(mean((x - r)^2)). Values that are not finite in either image are
// left out and counted.
struct LinearMetrics {
    double relmse = 0;
    double rmse = 0;
    long long nonfinite = 0;  // RGB values left out
};

// SSIM (Wang, Bovik, Sheikh, Simoncelli 2004, "Image quality assessment: from error
// visibility to structural similarity") of the Rec. 601 lumas of a and b (0.299 R + 0.587 G +
// 0.114 B on the 8-bit values), with the paper's parameters: an 11x11 Gaussian window of
// sigma 1.5, K1 = 0.01, K2 = 0.03, L = 255. The mean over every window position that lies
// wholly inside the image (no padding); an image smaller than 11 pixels in a direction uses
// the largest window that fits. 1 for identical images. Sizes must match.
double compute_ssim(const Rgb8Image& a, const Rgb8Image& b);

// Reads an image file as 8-bit RGB. Integer files are rescaled to 8 bits by OpenImageIO
// (16-bit v -> round(v * 255 / 65535)); float files (exr, hdr) are sRGB-encoded and quantized
// as glint writes PNG. Gray images are spread to RGB; alpha is ignored. Throws
// Error(MissingFile) when the file cannot be opened or read.
Rgb8Image read_rgb8(const std::string& path);

// Reads an image file as linear RGB: float files (exr, hdr) as stored, 8/16-bit files
// decoded from sRGB (what glint writes for a linear working space). Gray spreads to RGB, alpha
// is ignored. Throws Error(MissingFile) like read_rgb8.
LinearImage read_linear(const std::string& path);

// The 8-bit sRGB image glint would write as PNG for these linear values (read_rgb8 of a float
// file gives the same).
Rgb8Image encode_srgb8(const LinearImage& image);

// Throws Error(Usage) when the sizes differ. `reference` is r in the formulas.
LinearMetrics compare_linear(const LinearImage& image, const LinearImage& reference);

// |a - b| per linear value (non-finite differences 0), as a linear image: what
// `glint compare --diff OUT.exr` writes.
LinearImage linear_difference(const LinearImage& a, const LinearImage& b);

// Writes linear RGB as a float EXR (atomically). Throws Error(Output).
void write_linear_exr(const LinearImage& image, const std::string& path);

// Throws Error(Usage) when the sizes differ (naming both sizes).
CompareResult compare_images(const Rgb8Image& a, const Rgb8Image& b, double tolerance);

// |a - b| per channel, scaled so the largest difference becomes 255 (all black when the
// images are equal); what `glint compare --diff` writes as PNG.
Rgb8Image difference_image(const Rgb8Image& a, const Rgb8Image& b);

// Writes 8-bit RGB as PNG (atomically, like write_image). Throws Error(Output).
void write_rgb8_png(const Rgb8Image& image, const std::string& path);

// The contract line: `within=<fraction> rmse=<x> max=<d>@<x>,<y> pixels=<n> mae=<x> ssim=<s>
// relmse=<x> rmse_linear=<x>` (fields after `pixels` were added later; readers find fields by
// name).
std::string format_compare_line(const CompareResult& r);

}  // namespace glint::io
