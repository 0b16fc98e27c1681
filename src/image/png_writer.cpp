#include "image/png_writer.h"

#include <png.h>

#include <csetjmp>
#include <cstdint>
#include <cstring>

namespace glint {
namespace {

struct WriteState {
    std::vector<unsigned char>* bytes;
    std::string error;
};

void on_write(png_structp png, png_bytep data, png_size_t length) {
    auto* state = static_cast<WriteState*>(png_get_io_ptr(png));
    state->bytes->insert(state->bytes->end(), data, data + length);
}
void on_flush(png_structp) {}
void on_error(png_structp png, png_const_charp message) {
    auto* state = static_cast<WriteState*>(png_get_error_ptr(png));
    state->error = message ? message : "libpng error";
    png_longjmp(png, 1);
}
void on_warning(png_structp, png_const_charp) {}

const std::string* string_attribute(const ImageWrite& w, const char* name) {
    for (const auto& [key, value] : w.attributes)
        if (key == name) return std::get_if<std::string>(&value);
    return nullptr;
}

}  // namespace

bool png_writer_accepts(const ImageWrite& w) {
    if (w.format != "png" || w.to_memory == false) return false;
    if (w.channels != 1 && w.channels != 3) return false;  // alpha: OpenImageIO's conventions
    if (w.type != PixelType::UInt8 && w.type != PixelType::UInt16) return false;
    for (const auto& [key, value] : w.attributes) {
        // Without alpha, the 8-bit hints (compression, unassociated alpha) change nothing.
        const bool known = std::holds_alternative<std::string>(value) ||
                           (key == "oiio:Gamma" && std::holds_alternative<float>(value)) ||
                           key == "CompressionQuality" || key == "oiio:UnassociatedAlpha";
        if (!known) return false;
    }
    return w.width > 0 && w.height > 0 && w.data != nullptr;
}

std::string encode_png(const ImageWrite& w, std::vector<unsigned char>* bytes) {
    WriteState state{bytes, {}};
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, on_error, on_warning);
    if (!png) return "libpng: out of memory";
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return "libpng: out of memory";
    }
    // Everything libpng is given below must outlive a longjmp back here.
    std::vector<std::string> keys, texts;
    std::vector<png_text> text;
    std::vector<unsigned char> row;
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return state.error.empty() ? "libpng error" : state.error;
    }
    png_set_write_fn(png, &state, on_write, on_flush);
    const int depth = w.type == PixelType::UInt16 ? 16 : 8;
    png_set_IHDR(png, info, static_cast<png_uint_32>(w.width), static_cast<png_uint_32>(w.height),
                 depth, w.channels == 3 ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_GRAY,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    const std::string* colorspace = string_attribute(w, "oiio:ColorSpace");
    if (colorspace && *colorspace == "sRGB") {
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_ABSOLUTE);
    } else if (colorspace && *colorspace == "Linear") {
        png_set_gAMA(png, info, 1.0);
    } else if (!colorspace) {
        for (const auto& [key, value] : w.attributes)
            if (key == "oiio:Gamma" && std::get<float>(value) > 0)
                png_set_gAMA(png, info, 1.0 / static_cast<double>(std::get<float>(value)));
    }
    for (const auto& [key, value] : w.attributes) {
        const auto* s = std::get_if<std::string>(&value);
        if (!s || key.rfind("oiio:", 0) == 0) continue;
        keys.push_back(key == "ImageDescription" ? "Description" : key.substr(0, 79));
        texts.push_back(*s);
    }
    text.resize(keys.size());
    for (size_t i = 0; i < keys.size(); ++i) {
        std::memset(&text[i], 0, sizeof text[i]);
        text[i].compression = PNG_TEXT_COMPRESSION_NONE;
        text[i].key = keys[i].data();
        text[i].text = texts[i].data();
        text[i].text_length = texts[i].size();
    }
    if (!text.empty()) png_set_text(png, info, text.data(), static_cast<int>(text.size()));
    png_write_info(png, info);
    const size_t row_bytes = static_cast<size_t>(w.width) * w.channels * (depth / 8);
    const auto* src = static_cast<const unsigned char*>(w.data);
    row.resize(row_bytes);
    for (int y = 0; y < w.height; ++y) {
        const unsigned char* r = src + static_cast<size_t>(y) * row_bytes;
        if (depth == 16) {
            // PNG stores 16-bit samples big-endian.
            for (size_t i = 0; i < row_bytes; i += 2) {
                uint16_t v;
                std::memcpy(&v, r + i, 2);
                row[i] = static_cast<unsigned char>(v >> 8);
                row[i + 1] = static_cast<unsigned char>(v & 0xff);
            }
        } else {
            std::memcpy(row.data(), r, row_bytes);
        }
        png_write_row(png, row.data());
    }
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return {};
}

}  // namespace glint
