// Image files through OpenImageIO, loaded when first needed. Debian's OpenImageIO pulls in
// some 260 shared libraries (OpenCV, GDAL, FFmpeg, GStreamer...), whose loading and static
// initialisers cost about 350 ms and 130 MB before main() would run; a scene that reads no
// image and writes PNG (image/png_writer.h) never loads it. The OpenImageIO side is the module
// src/image/oiio/oiio_module.cpp (libglint_oiio.so); this interface has no OpenImageIO types.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace glint {

enum class PixelType { UInt8, UInt16, Half, Float, Double, Other };

inline bool is_float_pixel(PixelType t) {
    return t == PixelType::Half || t == PixelType::Float || t == PixelType::Double;
}

struct ImageHeader {
    int width = 0, height = 0, channels = 0;
    PixelType type = PixelType::Other;
    int alpha_channel = -1;  // -1: none named by the file
    std::string format;      // OpenImageIO's reader name: "png", "openexr", ...
    std::string colorspace;  // OpenImageIO's oiio:ColorSpace ("sRGB", "Linear", "GammaX.Y", ...)
    float gamma = 0;         // oiio:Gamma, 0 when absent
    std::vector<std::pair<std::string, std::string>> text;  // the string metadata
};

// An opened image: its header, then its pixels.
class ImageReader {
public:
    virtual ~ImageReader() = default;
    virtual const ImageHeader& header() const = 0;
    // The first `channels` channels of every pixel as floats (integers scaled to [0, 1]),
    // rows top to bottom. Returns the reason it failed, empty on success.
    virtual std::string read(int channels, float* out) = 0;
};

using ImageAttribute = std::variant<std::string, int, float>;
using ImageAttributes = std::vector<std::pair<std::string, ImageAttribute>>;

struct ImageWrite {
    std::string path;    // the file OpenImageIO opens (its extension does not matter)
    std::string format;  // OpenImageIO's writer name: "png", "openexr", "tiff", ...
    int width = 0, height = 0, channels = 0;
    int alpha_channel = -1;
    PixelType type = PixelType::UInt8;  // of `data`, which the file stores unconverted
    std::vector<std::string> channel_names;  // empty: OpenImageIO's defaults (R, G, B, A)
    const void* data = nullptr;
    ImageAttributes attributes;
    // Encode into `bytes` instead of writing `path` (which is then only the name).
    bool to_memory = false;
};

// Drawing for the report plots: a white canvas, lines, boxes and text.
struct DrawOp {
    enum class Kind { Line, Box, FilledBox, Text } kind = Kind::Line;
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    float color[3] = {0, 0, 0};
    std::string text, font;
    int font_size = 0;
    int align_x = 0, align_y = 0;  // -1 left/top, 0 centre, 1 right/bottom; y -2: baseline
};

class ImageLibrary {
public:
    virtual ~ImageLibrary() = default;
    // `config`: OpenImageIO open-time hints (e.g. oiio:UnassociatedAlpha). Null and *error set
    // when the file cannot be opened.
    virtual std::unique_ptr<ImageReader> open(
        const std::string& path, const std::vector<std::pair<std::string, int>>& config,
        std::string* error) const = 0;
    // Returns the reason it failed, empty on success.
    virtual std::string write(const ImageWrite& w, std::vector<unsigned char>* bytes) const = 0;
    // Draws ops in order on a white w x h canvas; *rgb gets 3 floats per pixel. Returns the
    // reason text could not be drawn (the rest is drawn regardless), empty otherwise.
    virtual std::string draw(int w, int h, const std::vector<DrawOp>& ops,
                             std::vector<float>* rgb) const = 0;
};

// The module, loaded on the first call: $GLINT_IMAGE_MODULE, else libglint_oiio.so beside
// the running executable, else the one this build made. Throws glint::Error (ErrorKind::Output)
// when none loads.
const ImageLibrary& image_library();


}  // namespace glint
