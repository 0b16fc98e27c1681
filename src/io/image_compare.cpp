#include "io/image_compare.h"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "core/error.h"
#include "io/color_encoding.h"
#include "io/image_output.h"
#include "render/image.h"

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

}  // namespace

Rgb8Image read_rgb8(const std::string& path) {
    auto fail = [&](const std::string& why) {
        return Error(ErrorKind::MissingFile, {}, "cannot read image " + path + ": " + why);
    };
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) {
        std::string why = OIIO::geterror();
        throw fail(why.empty() ? "cannot open the file" : why);
    }
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    if (spec.width <= 0 || spec.height <= 0 || channels <= 0) throw fail("empty image");
    if (channels == 2) throw fail("gray+alpha images are not supported");
    Rgb8Image out;
    out.width = spec.width;
    out.height = spec.height;
    const size_t pixels = static_cast<size_t>(spec.width) * spec.height;
    const bool is_float = spec.format.basetype == OIIO::TypeDesc::FLOAT ||
                          spec.format.basetype == OIIO::TypeDesc::HALF ||
                          spec.format.basetype == OIIO::TypeDesc::DOUBLE;
    if (is_float) {
        std::vector<float> data(pixels * channels);
        if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data()))
            throw fail(in->geterror());
        std::vector<float> rgb = to_rgb(data, pixels, channels);
        render::Image linear;
        linear.width = spec.width;
        linear.height = spec.height;
        linear.rgba.resize(pixels * 4, 1.0f);
        for (size_t i = 0; i < pixels; ++i)
            for (int c = 0; c < 3; ++c) linear.rgba[i * 4 + c] = rgb[i * 3 + c];
        OutputEncoding srgb;  // sRGB, linear working space: what a PNG of this film holds
        std::vector<float> encoded = encode_rgb(linear, srgb);
        out.rgb.resize(pixels * 3);
        for (size_t i = 0; i < encoded.size(); ++i)
            out.rgb[i] = static_cast<unsigned char>(quantize(encoded[i], 255));
    } else {
        std::vector<unsigned char> data(pixels * channels);
        if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, data.data()))
            throw fail(in->geterror());
        out.rgb = to_rgb(data, pixels, channels);
    }
    in->close();
    return out;
}

CompareResult compare_images(const Rgb8Image& a, const Rgb8Image& b, double tolerance) {
    if (a.width != b.width || a.height != b.height)
        throw Error(ErrorKind::Usage, {},
                    "image sizes differ: " + std::to_string(a.width) + "x" +
                        std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" +
                        std::to_string(b.height));
    CompareResult r;
    r.pixels = static_cast<long long>(a.width) * a.height;
    double sum_sq = 0;
    r.max_diff = -1;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            size_t i = (static_cast<size_t>(y) * a.width + x) * 3;
            int largest = 0;
            for (int c = 0; c < 3; ++c) {
                int d = std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c]));
                largest = std::max(largest, d);
                sum_sq += double(d) * d;
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
    render::Image film;
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
    std::snprintf(buf, sizeof buf, "within=%.6f rmse=%.4f max=%d@%d,%d pixels=%lld",
                  r.within_fraction, r.rmse, r.max_diff, r.max_x, r.max_y, r.pixels);
    return buf;
}

}  // namespace glint::io
