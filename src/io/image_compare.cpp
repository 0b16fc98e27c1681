#include "io/image_compare.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "core/error.h"
#include "image/image_library.h"
#include "io/color_encoding.h"
#include "io/image_output.h"
#include "image/image.h"

namespace glint::io {

namespace {

// Spreads the first channels of interleaved data to RGB: gray -> (g, g, g), RGB(A) -> RGB.
template <typename T>
std::vector<T> to_rgb(const std::vector<T>& data, size_t pixels, int channels) {
    std::vector<T> rgb(pixels * 3);
    for (size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = data[i * channels + (channels >= 3 ? c : 0)];
    return rgb;
}

// Normalized 1-D Gaussian weights of `size` taps and the given sigma, centred.
std::vector<double> gaussian_taps(int size, double sigma) {
    std::vector<double> w(size);
    double sum = 0, c = (size - 1) / 2.0;
    for (int i = 0; i < size; ++i) sum += w[i] = std::exp(-(i - c) * (i - c) / (2 * sigma * sigma));
    for (double& v : w) v /= sum;
    return w;
}

// Separable weighted sums over every window position wholly inside a w x h plane:
// out is (w - taps_x + 1) x (h - taps_y + 1).
std::vector<double> window_filter(const std::vector<double>& plane, int w, int h,
                                  const std::vector<double>& tx, const std::vector<double>& ty) {
    const int ow = w - static_cast<int>(tx.size()) + 1;
    const int oh = h - static_cast<int>(ty.size()) + 1;
    std::vector<double> rows(static_cast<size_t>(ow) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < ow; ++x) {
            double s = 0;
            for (size_t k = 0; k < tx.size(); ++k) s += tx[k] * plane[size_t(y) * w + x + k];
            rows[size_t(y) * ow + x] = s;
        }
    std::vector<double> out(static_cast<size_t>(ow) * oh);
    for (int y = 0; y < oh; ++y)
        for (int x = 0; x < ow; ++x) {
            double s = 0;
            for (size_t k = 0; k < ty.size(); ++k) s += ty[k] * rows[(y + k) * ow + x];
            out[size_t(y) * ow + x] = s;
        }
    return out;
}

}  // namespace

double compute_ssim(const Rgb8Image& a, const Rgb8Image& b) {
    if (a.width != b.width || a.height != b.height)
        throw Error(ErrorKind::Usage, {}, "image sizes differ");
    const int w = a.width, h = a.height;
    if (w <= 0 || h <= 0) return 1.0;
    constexpr int kWindow = 11;
    constexpr double kSigma = 1.5;
    constexpr double kC1 = (0.01 * 255) * (0.01 * 255);
    constexpr double kC2 = (0.03 * 255) * (0.03 * 255);
    const size_t n = static_cast<size_t>(w) * h;
    std::vector<double> la(n), lb(n), aa(n), bb(n), ab(n);
    for (size_t i = 0; i < n; ++i) {
        const unsigned char* pa = &a.rgb[i * 3];
        const unsigned char* pb = &b.rgb[i * 3];
        la[i] = 0.299 * pa[0] + 0.587 * pa[1] + 0.114 * pa[2];
        lb[i] = 0.299 * pb[0] + 0.587 * pb[1] + 0.114 * pb[2];
        aa[i] = la[i] * la[i];
        bb[i] = lb[i] * lb[i];
        ab[i] = la[i] * lb[i];
    }
    const std::vector<double> tx = gaussian_taps(std::min(kWindow, w), kSigma);
    const std::vector<double> ty = gaussian_taps(std::min(kWindow, h), kSigma);
    const std::vector<double> mu_a = window_filter(la, w, h, tx, ty);
    const std::vector<double> mu_b = window_filter(lb, w, h, tx, ty);
    const std::vector<double> e_aa = window_filter(aa, w, h, tx, ty);
    const std::vector<double> e_bb = window_filter(bb, w, h, tx, ty);
    const std::vector<double> e_ab = window_filter(ab, w, h, tx, ty);
    double sum = 0;
    for (size_t i = 0; i < mu_a.size(); ++i) {
        const double ma = mu_a[i], mb = mu_b[i];
        const double va = e_aa[i] - ma * ma, vb = e_bb[i] - mb * mb, cov = e_ab[i] - ma * mb;
        sum += ((2 * ma * mb + kC1) * (2 * cov + kC2)) /
               ((ma * ma + mb * mb + kC1) * (va + vb + kC2));
    }
    return sum / double(mu_a.size());
}

namespace {

// An image file opened for reading, with the checks both readers make.
struct OpenedImage {
    std::unique_ptr<ImageReader> in;
    int width = 0, height = 0, channels = 0;
    size_t pixels = 0;
    bool is_float = false;  // stored as float, half or double (EXR, HDR): linear values
};

Error read_error(const std::string& path, const std::string& why) {
    return Error(ErrorKind::MissingFile, {}, "cannot read image " + path + ": " + why);
}

OpenedImage open_image(const std::string& path) {
    OpenedImage img;
    std::string why;
    img.in = image_library().open(path, {}, &why);
    if (!img.in) throw read_error(path, why);
    const ImageHeader& spec = img.in->header();
    img.width = spec.width;
    img.height = spec.height;
    img.channels = spec.channels;
    if (img.width <= 0 || img.height <= 0 || img.channels <= 0)
        throw read_error(path, "empty image");
    if (img.channels == 2) throw read_error(path, "gray+alpha images are not supported");
    img.pixels = static_cast<size_t>(img.width) * img.height;
    img.is_float = is_float_pixel(spec.type);
    return img;
}

// All channels of the image as floats (integer formats scaled to [0, 1]).
std::vector<float> read_all(const std::string& path, OpenedImage& img) {
    std::vector<float> data(img.pixels * img.channels);
    const std::string why = img.in->read(img.channels, data.data());
    if (!why.empty()) throw read_error(path, why);
    img.in.reset();
    return data;
}

// 8-bit code values of [0, 1] floats (clipped, rounded to nearest).
std::vector<unsigned char> to_u8(const std::vector<float>& v) {
    std::vector<unsigned char> out(v.size());
    for (size_t i = 0; i < v.size(); ++i) out[i] = static_cast<unsigned char>(quantize(v[i], 255));
    return out;
}

}  // namespace

Rgb8Image read_rgb8(const std::string& path) {
    OpenedImage img = open_image(path);
    if (img.is_float) {
        LinearImage linear;
        linear.width = img.width;
        linear.height = img.height;
        linear.rgb = to_rgb(read_all(path, img), img.pixels, img.channels);
        return encode_srgb8(linear);
    }
    Rgb8Image out;
    out.width = img.width;
    out.height = img.height;
    out.rgb = to_rgb(to_u8(read_all(path, img)), img.pixels, img.channels);
    return out;
}

LinearImage read_linear(const std::string& path) {
    OpenedImage img = open_image(path);
    LinearImage out;
    out.width = img.width;
    out.height = img.height;
    out.rgb = to_rgb(read_all(path, img), img.pixels, img.channels);
    if (!img.is_float) {
        // IEC 61966-2-1 sRGB decoding of the code values OpenImageIO scaled to [0, 1].
        for (float& v : out.rgb)
            v = v <= 0.04045f ? v / 12.92f
                              : static_cast<float>(std::pow((v + 0.055) / 1.055, 2.4));
    }
    return out;
}

Rgb8Image encode_srgb8(const LinearImage& image) {
    const size_t pixels = static_cast<size_t>(image.width) * image.height;
    Image linear;
    linear.width = image.width;
    linear.height = image.height;
    linear.rgba.resize(pixels * 4, 1.0f);
    for (size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c) linear.rgba[i * 4 + c] = image.rgb[i * 3 + c];
    OutputEncoding srgb;  // sRGB, linear working space: what a PNG of this film holds
    std::vector<float> encoded = encode_rgb(linear, srgb);
    Rgb8Image out;
    out.width = image.width;
    out.height = image.height;
    out.rgb.resize(pixels * 3);
    for (size_t i = 0; i < encoded.size(); ++i)
        out.rgb[i] = static_cast<unsigned char>(quantize(encoded[i], 255));
    return out;
}

LinearMetrics compare_linear(const LinearImage& image, const LinearImage& reference) {
    if (image.width != reference.width || image.height != reference.height)
        throw Error(ErrorKind::Usage, {},
                    "image sizes differ: " + std::to_string(image.width) + "x" +
                        std::to_string(image.height) + " vs " + std::to_string(reference.width) +
                        "x" + std::to_string(reference.height));
    LinearMetrics m;
    double rel = 0, sq = 0;
    long long n = 0;
    for (size_t i = 0; i < image.rgb.size(); ++i) {
        const double x = image.rgb[i], r = reference.rgb[i];
        if (!std::isfinite(x) || !std::isfinite(r)) {
            ++m.nonfinite;
            continue;
        }
        const double d2 = (x - r) * (x - r);
        rel += d2 / (r * r + 0.01);
        sq += d2;
        ++n;
    }
    if (n > 0) {
        m.relmse = rel / double(n);
        m.rmse = std::sqrt(sq / double(n));
    }
    return m;
}

LinearImage linear_difference(const LinearImage& a, const LinearImage& b) {
    if (a.width != b.width || a.height != b.height)
        throw Error(ErrorKind::Usage, {}, "image sizes differ");
    LinearImage d = a;
    for (size_t i = 0; i < d.rgb.size(); ++i) {
        const float v = std::fabs(a.rgb[i] - b.rgb[i]);
        d.rgb[i] = std::isfinite(v) ? v : 0.0f;
    }
    return d;
}

void write_linear_exr(const LinearImage& image, const std::string& path) {
    Image film;
    film.width = image.width;
    film.height = image.height;
    film.rgba.resize(static_cast<size_t>(image.width) * image.height * 4, 1.0f);
    for (size_t i = 0; i < film.rgba.size() / 4; ++i)
        for (int c = 0; c < 3; ++c) film.rgba[i * 4 + c] = image.rgb[i * 3 + c];
    write_float_exr(film, path, 3);
}

CompareResult compare_images(const Rgb8Image& a, const Rgb8Image& b, double tolerance) {
    if (a.width != b.width || a.height != b.height)
        throw Error(ErrorKind::Usage, {},
                    "image sizes differ: " + std::to_string(a.width) + "x" +
                        std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" +
                        std::to_string(b.height));
    CompareResult r;
    r.pixels = static_cast<long long>(a.width) * a.height;
    double sum_sq = 0, sum_abs = 0;
    r.max_diff = -1;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            size_t i = (static_cast<size_t>(y) * a.width + x) * 3;
            int largest = 0;
            for (int c = 0; c < 3; ++c) {
                int d = std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c]));
                largest = std::max(largest, d);
                sum_sq += double(d) * d;
                sum_abs += d;
            }
            if (largest <= tolerance) ++r.within_count;
            if (largest > r.max_diff) {
                r.max_diff = largest;
                r.max_x = x;
                r.max_y = y;
            }
        }
    }
    if (r.max_diff < 0) r.max_diff = 0;
    r.within_fraction = r.pixels > 0 ? double(r.within_count) / double(r.pixels) : 1.0;
    r.rmse = r.pixels > 0 ? std::sqrt(sum_sq / (3.0 * double(r.pixels))) : 0.0;
    r.mae = r.pixels > 0 ? sum_abs / (3.0 * double(r.pixels)) : 0.0;
    r.ssim = compute_ssim(a, b);
    return r;
}

Rgb8Image difference_image(const Rgb8Image& a, const Rgb8Image& b) {
    if (a.width != b.width || a.height != b.height)
        throw Error(ErrorKind::Usage, {}, "image sizes differ");
    Rgb8Image d;
    d.width = a.width;
    d.height = a.height;
    d.rgb.resize(a.rgb.size());
    int max_diff = 0;
    for (size_t i = 0; i < a.rgb.size(); ++i) {
        int v = std::abs(int(a.rgb[i]) - int(b.rgb[i]));
        d.rgb[i] = static_cast<unsigned char>(v);
        max_diff = std::max(max_diff, v);
    }
    if (max_diff > 0)
        for (unsigned char& v : d.rgb)
            v = static_cast<unsigned char>((v * 255 + max_diff / 2) / max_diff);
    return d;
}

void write_rgb8_png(const Rgb8Image& image, const std::string& path) {
    // Through write_image with an identity encoding: the code values pass unchanged
    // (v / 255 quantizes back to v exactly), and the write is atomic.
    Image film;
    film.width = image.width;
    film.height = image.height;
    film.rgba.resize(static_cast<size_t>(image.width) * image.height * 4, 1.0f);
    for (size_t i = 0; i < film.rgba.size() / 4; ++i)
        for (int c = 0; c < 3; ++c) film.rgba[i * 4 + c] = image.rgb[i * 3 + c] / 255.0f;
    OutputEncoding identity;
    identity.transfer = OutputEncoding::Transfer::Linear;
    write_image(film, path, identity);
}

std::string format_compare_line(const CompareResult& r) {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "within=%.6f rmse=%.4f max=%d@%d,%d pixels=%lld mae=%.4f ssim=%.6f "
                  "relmse=%.6g rmse_linear=%.6g",
                  r.within_fraction, r.rmse, r.max_diff, r.max_x, r.max_y, r.pixels, r.mae,
                  r.ssim, r.relmse, r.rmse_linear);
    return buf;
}

}  // namespace glint::io
