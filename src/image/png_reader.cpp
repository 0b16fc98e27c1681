#include "image/png_reader.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>

namespace glint {
namespace {

// libpng reports errors by longjmp: nothing with a destructor lives in a frame between the
// setjmp and the libpng call that fails, and the message waits here.
struct PngState {
    std::FILE* file = nullptr;
    png_structp png = nullptr;
    png_infop info = nullptr;
    std::string error;

    ~PngState() {
        if (png) png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
        if (file) std::fclose(file);
    }
};

void on_read(png_structp png, png_bytep data, size_t length) {
    auto* s = static_cast<PngState*>(png_get_io_ptr(png));
    // OpenImageIO's words for a file that ends early, so that both readers say the same.
    if (std::fread(data, 1, length, s->file) != length)
        png_error(png, "Read error: hit end of file");
}

void on_error(png_structp png, png_const_charp message) {
    auto* s = static_cast<PngState*>(png_get_error_ptr(png));
    s->error = message && *message ? message : "libpng error";
    png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

// The header: PNG's transformations set up as OpenImageIO sets them, then what they give.
// Returns false with s->error set when libpng fails.
bool read_header(PngState* s, ImageHeader* h) {
    if (setjmp(png_jmpbuf(s->png))) return false;
    png_set_sig_bytes(s->png, 8);
    png_read_info(s->png, s->info);
    png_set_expand(s->png);  // 1, 2 and 4 bits to 8, palettes to RGB, tRNS to alpha
    if (png_get_bit_depth(s->png, s->info) == 16) png_set_swap(s->png);  // x86-64 byte order
    png_set_interlace_handling(s->png);
    png_read_update_info(s->png, s->info);
    h->width = static_cast<int>(png_get_image_width(s->png, s->info));
    h->height = static_cast<int>(png_get_image_height(s->png, s->info));
    h->channels = png_get_channels(s->png, s->info);
    h->type = png_get_bit_depth(s->png, s->info) == 16 ? PixelType::UInt16 : PixelType::UInt8;
    h->alpha_channel = h->channels == 2 || h->channels == 4 ? h->channels - 1 : -1;
    h->format = "png";
    h->colorspace = "sRGB";
    int intent = 0;
    double file_gamma = 0;
    if (!png_get_sRGB(s->png, s->info, &intent) && png_get_gAMA(s->png, s->info, &file_gamma) &&
        file_gamma > 0) {
        // The display gamma, to a hundredth (2.2, not 2.19998), as OpenImageIO gives it.
        float g = static_cast<float>(1.0 / file_gamma);
        g = std::round(100.0f * g) / 100.0f;
        h->gamma = g;
        if (g == 1.0f) {
            h->colorspace = "linear";
        } else {
            char name[32];
            std::snprintf(name, sizeof name, "Gamma%.2g", static_cast<double>(g));
            h->colorspace = name;
        }
    }
    return true;
}

bool read_rows(PngState* s, std::vector<png_bytep>& rows) {
    if (setjmp(png_jmpbuf(s->png))) return false;
    png_read_image(s->png, rows.data());
    png_read_end(s->png, nullptr);
    return true;
}

class PngReader final : public ImageReader {
  public:
    explicit PngReader(std::unique_ptr<PngState> s, const ImageHeader& h)
        : s_(std::move(s)), header_(h) {}

    const ImageHeader& header() const override { return header_; }

    std::string read(int channels, float* out) override {
        if (!s_) return "image already read";
        const auto w = static_cast<size_t>(header_.width), h = static_cast<size_t>(header_.height);
        const size_t nc = static_cast<size_t>(header_.channels);
        const size_t sample = header_.type == PixelType::UInt16 ? 2 : 1;
        const size_t row_bytes = png_get_rowbytes(s_->png, s_->info);
        if (row_bytes != w * nc * sample) return "unexpected PNG row size";
        std::vector<unsigned char> pixels(row_bytes * h);
        std::vector<png_bytep> rows(h);
        for (size_t y = 0; y < h; ++y) rows[y] = pixels.data() + y * row_bytes;
        if (!read_rows(s_.get(), rows)) return s_->error;
        s_.reset();
        const size_t take = std::min(nc, static_cast<size_t>(std::max(channels, 0)));
        for (size_t i = 0; i < w * h; ++i) {
            for (size_t c = 0; c < take; ++c) {
                const size_t at = i * nc + c;
                if (sample == 2) {
                    uint16_t v;
                    std::memcpy(&v, &pixels[2 * at], 2);
                    out[i * static_cast<size_t>(channels) + c] = v * (1.0f / 65535.0f);
                } else {
                    out[i * static_cast<size_t>(channels) + c] = pixels[at] * (1.0f / 255.0f);
                }
            }
            for (size_t c = take; c < static_cast<size_t>(channels); ++c)
                out[i * static_cast<size_t>(channels) + c] = 0;
        }
        return {};
    }

  private:
    std::unique_ptr<PngState> s_;
    ImageHeader header_;
};

}  // namespace

std::unique_ptr<ImageReader> open_png(const std::string& path, bool keep_unassociated_alpha,
                                      std::string* error) {
    error->clear();
    auto s = std::make_unique<PngState>();
    s->file = std::fopen(path.c_str(), "rb");
    if (!s->file) return nullptr;  // OpenImageIO says why, in its own words
    unsigned char signature[8];
    if (std::fread(signature, 1, 8, s->file) != 8 || png_sig_cmp(signature, 0, 8) != 0)
        return nullptr;
    s->png = png_create_read_struct(PNG_LIBPNG_VER_STRING, s.get(), on_error, on_warning);
    if (!s->png) return nullptr;
    s->info = png_create_info_struct(s->png);
    if (!s->info) return nullptr;
    png_set_read_fn(s->png, s.get(), on_read);
    ImageHeader h;
    if (!read_header(s.get(), &h)) {
        *error = s->error;
        return nullptr;
    }
    // OpenImageIO multiplies colour by alpha unless asked not to: that is its to do.
    if (h.alpha_channel >= 0 && !keep_unassociated_alpha) return nullptr;
    return std::make_unique<PngReader>(std::move(s), h);
}

std::unique_ptr<ImageReader> open_image(const std::string& path,
                                        const std::vector<std::pair<std::string, int>>& config,
                                        std::string* error) {
    bool unassociated = false;
    for (const auto& [key, value] : config)
        if (key == "oiio:UnassociatedAlpha") unassociated = value != 0;
    std::unique_ptr<ImageReader> in = open_png(path, unassociated, error);
    if (in || !error->empty()) return in;
    return image_library().open(path, config, error);
}

}  // namespace glint
