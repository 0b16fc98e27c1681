#include "io/image_output.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

#include "core/error.h"
#include "image/image_library.h"
#include "io/color_encoding.h"
#include "image/png_writer.h"

namespace glint::io {

namespace {

namespace fs = std::filesystem;

struct FormatInfo {
    const char* extension;
    const char* oiio_name;
    bool is_float;       // scene-referred: linear values, no OpenColorIO
    unsigned max_value;  // integer formats: the code value of 1.0
    bool supports_alpha;
};

constexpr FormatInfo kFormats[] = {
    {"png", "png", false, 255, true},     {"jpg", "jpeg", false, 255, false},
    {"jpeg", "jpeg", false, 255, false},  {"tif", "tiff", false, 65535, true},
    {"tiff", "tiff", false, 65535, true}, {"exr", "openexr", true, 0, true},
    {"hdr", "hdr", true, 0, false},
};

const FormatInfo& format_info(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    if (!ext.empty() && ext[0] == '.') ext.erase(0, 1);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const FormatInfo& f : kFormats)
        if (ext == f.extension) return f;
    throw Error(ErrorKind::Output, {},
                "unsupported output format '" + (ext.empty() ? std::string("(none)") : ext) +
                    "' for " + path + " (use .png, .exr, .tif, .hdr or .jpg)");
}

// Removes the temporary file unless the write succeeded and it was renamed.
class TempFile {
  public:
    explicit TempFile(std::string path) : path_(std::move(path)) {}
    ~TempFile() {
        if (!path_.empty()) {
            std::error_code ec;
            fs::remove(path_, ec);
        }
    }
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;
    const std::string& path() const { return path_; }
    void release() { path_.clear(); }

  private:
    std::string path_;
};

std::string temp_name(const std::string& path) {
    return path + ".tmp-" + std::to_string(static_cast<long>(::getpid()));
}

// Writes `bytes` to a new file and flushes it to the disk. Returns the reason it failed (a
// full disk, a file size limit, an I/O error), empty on success. OpenImageIO's own file
// writers do not all report failed writes (its PNG writer does not), so the encoded file is
// written here, every call checked.
std::string write_file(const std::string& path, const std::vector<unsigned char>& bytes) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) return std::strerror(errno);
    size_t written = 0;
    while (written < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int err = n < 0 ? errno : ENOSPC;
            ::close(fd);
            return std::strerror(err);
        }
        written += static_cast<size_t>(n);
    }
    // Some file systems report a full disk only here.
    if (::fsync(fd) != 0 && errno != EINVAL) {
        const int err = errno;
        ::close(fd);
        return std::strerror(err);
    }
    if (::close(fd) != 0) return std::strerror(errno);
    return {};
}

// Flushes a file written by someone else to the disk (a full disk may show only here).
// Returns the reason it failed, empty on success.
std::string flush_file(const std::string& path) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) return std::strerror(errno);
    if (::fsync(fd) != 0 && errno != EINVAL) {
        const int err = errno;
        ::close(fd);
        return std::strerror(err);
    }
    if (::close(fd) != 0) return std::strerror(errno);
    return {};
}

// Writes through a temporary beside the target (so the rename stays on one file system) and
// renames it, so a failed write never leaves a partial file.
void write_atomically(const std::string& path, ImageWrite w, const ImageMetadata& metadata,
                      OutputBatch* batch) {
    for (const auto& [name, value] : metadata) w.attributes.emplace_back(name, value);
    TempFile temp(temp_name(path));
    auto fail = [&](const std::string& why) {
        return Error(ErrorKind::Output, {}, "cannot write " + path + ": " + why);
    };
    {
        // Encoded in memory, then written by write_file; except TIFF, whose writer (libtiff)
        // reports its own write errors and, in OpenImageIO 2.4, writes an unreadable file (no
        // image directory) through a memory proxy: it writes the temporary itself, which is
        // then flushed to the disk like the others. PNGs without alpha are encoded by libpng
        // directly, so that a render writing one never loads OpenImageIO.
        const bool via_memory = w.format != "tiff";
        w.path = temp.path();
        w.to_memory = via_memory;
        std::vector<unsigned char> bytes;
        std::string why = png_writer_accepts(w) ? encode_png(w, &bytes)
                                                : image_library().write(w, &bytes);
        if (!why.empty()) throw fail(why);
        why = via_memory ? write_file(temp.path(), bytes) : flush_file(temp.path());
        if (!why.empty()) throw fail(why);
    }
    if (batch) {
        batch->add(temp.path(), path);
        temp.release();
        return;
    }
    std::error_code ec;
    fs::rename(temp.path(), path, ec);
    if (ec) throw fail(ec.message());
    temp.release();
}

}  // namespace

OutputBatch::~OutputBatch() {
    for (const auto& [temp, path] : staged_) {
        std::error_code ec;
        fs::remove(temp, ec);
    }
}

void OutputBatch::commit() {
    while (!staged_.empty()) {
        const auto& [temp, path] = staged_.front();
        std::error_code ec;
        fs::rename(temp, path, ec);
        if (ec) throw Error(ErrorKind::Output, {}, "cannot write " + path + ": " + ec.message());
        staged_.erase(staged_.begin());
    }
}

void check_writable(const std::string& path) {
    auto fail = [&](const std::string& why) {
        return Error(ErrorKind::Output, {}, "cannot write " + path + ": " + why);
    };
    const fs::path parent = fs::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty() && !fs::is_directory(parent, ec))
        throw fail("folder " + parent.string() + " does not exist");
    if (fs::is_directory(path, ec)) throw fail("it is a folder");
    const std::string temp = temp_name(path);
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) {
        const int err = errno;
        if (err == EEXIST) return;  // our own temporary name: writable enough
        throw fail(std::strerror(err));
    }
    ::close(fd);
    ::unlink(temp.c_str());
}

std::string output_format_for(const std::string& path) { return format_info(path).oiio_name; }

bool is_float_format(const std::string& path) { return format_info(path).is_float; }

void write_image(const Image& image, const std::string& path,
                 const OutputEncoding& encoding, const ImageMetadata& metadata,
                 OutputBatch* batch) {
    const FormatInfo& format = format_info(path);
    if (image.width <= 0 || image.height <= 0 ||
        image.rgba.size() != static_cast<size_t>(image.width) * image.height * 4)
        throw Error(ErrorKind::Output, {}, "cannot write " + path + ": the image is empty");

    const int channels = (encoding.alpha && format.supports_alpha) ? 4 : 3;
    const size_t pixels = static_cast<size_t>(image.width) * image.height;
    ImageWrite spec;
    spec.format = format.oiio_name;
    spec.width = image.width;
    spec.height = image.height;
    spec.channels = channels;
    spec.type = format.is_float           ? PixelType::Float
                : format.max_value == 255 ? PixelType::UInt8
                                          : PixelType::UInt16;
    if (channels == 4) spec.alpha_channel = 3;
    auto attribute = [&](const char* name, ImageAttribute value) {
        spec.attributes.emplace_back(name, std::move(value));
    };

    // Pixel data in the file's own type, so OpenImageIO does no conversion of its own.
    std::vector<float> float_data;
    std::vector<uint8_t> u8_data;
    std::vector<uint16_t> u16_data;
    const void* data = nullptr;
    if (format.is_float) {
        attribute("oiio:ColorSpace", std::string("Linear"));
        std::vector<float> linear = linear_rgba(image, encoding);
        float_data.resize(pixels * channels);
        for (size_t i = 0; i < pixels; ++i)
            for (int c = 0; c < channels; ++c) float_data[i * channels + c] = linear[i * 4 + c];
        data = float_data.data();
    } else if (encoding.view.active()) {
        // Blender's display image of the linear values the float formats get; alpha 1 when
        // the file has none, as Blender reads an RGB EXR.
        if (encoding.view.view == "Standard") attribute("oiio:ColorSpace", std::string("sRGB"));
        // Blender writes 8-bit files with straight alpha (PNG's; OpenImageIO must not divide
        // again) and 16-bit TIFF premultiplied (TIFF's associated alpha), each as it stores it.
        const bool eight_bit = format.max_value == 255;
        if (eight_bit) attribute("oiio:UnassociatedAlpha", 1);
        if (eight_bit) attribute("CompressionQuality", 95);
        std::vector<float> linear = linear_rgba(image, encoding);
        if (channels == 3)
            for (size_t i = 0; i < pixels; ++i) linear[i * 4 + 3] = 1.0f;
        const std::vector<float> shown =
            view_rgba(linear, image.width, image.height, encoding.view, eight_bit);
        u8_data.resize(eight_bit ? pixels * channels : 0);
        u16_data.resize(eight_bit ? 0 : pixels * channels);
        for (size_t i = 0; i < pixels; ++i)
            for (int c = 0; c < channels; ++c) {
                const float v = shown[i * 4 + c];
                if (eight_bit)
                    u8_data[i * channels + c] = static_cast<uint8_t>(quantize(v, 255));
                else
                    u16_data[i * channels + c] = static_cast<uint16_t>(quantize_blender16(v));
            }
        data = eight_bit ? static_cast<const void*>(u8_data.data())
                         : static_cast<const void*>(u16_data.data());
    } else {
        if (encoding.transfer == OutputEncoding::Transfer::Srgb)
            attribute("oiio:ColorSpace", std::string("sRGB"));
        else if (encoding.transfer == OutputEncoding::Transfer::Gamma)
            attribute("oiio:Gamma", static_cast<float>(encoding.gamma));
        if (format.max_value == 255) attribute("CompressionQuality", 95);
        std::vector<float> rgb = encode_rgb(image, encoding);
        // Alpha is coverage, stored linearly (POV-Ray's IntEncode without a curve).
        auto code = [&](size_t i, int c) {
            float v = c < 3 ? rgb[i * 3 + c] : image.rgba[i * 4 + 3];
            return quantize(v, format.max_value);
        };
        if (format.max_value == 255) {
            u8_data.resize(pixels * channels);
            for (size_t i = 0; i < pixels; ++i)
                for (int c = 0; c < channels; ++c)
                    u8_data[i * channels + c] = static_cast<uint8_t>(code(i, c));
            data = u8_data.data();
        } else {
            u16_data.resize(pixels * channels);
            for (size_t i = 0; i < pixels; ++i)
                for (int c = 0; c < channels; ++c)
                    u16_data[i * channels + c] = static_cast<uint16_t>(code(i, c));
            data = u16_data.data();
        }
    }

    spec.data = data;
    write_atomically(path, std::move(spec), metadata, batch);
}

void write_float_exr(const Image& image, const std::string& path, int channels,
                     const ImageMetadata& metadata, OutputBatch* batch) {
    if (channels != 1 && channels != 3)
        throw Error(ErrorKind::Output, {}, "cannot write " + path + ": 1 or 3 channels only");
    if (image.width <= 0 || image.height <= 0 ||
        image.rgba.size() != static_cast<size_t>(image.width) * image.height * 4)
        throw Error(ErrorKind::Output, {}, "cannot write " + path + ": the image is empty");
    const size_t pixels = static_cast<size_t>(image.width) * image.height;
    ImageWrite spec;
    spec.format = "openexr";
    spec.width = image.width;
    spec.height = image.height;
    spec.channels = channels;
    spec.type = PixelType::Float;
    if (channels == 1) spec.channel_names = {"Z"};
    spec.attributes.emplace_back("oiio:ColorSpace", std::string("Linear"));
    std::vector<float> data(pixels * channels);
    for (size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < channels; ++c) data[i * channels + c] = image.rgba[i * 4 + c];
    spec.data = data.data();
    write_atomically(path, std::move(spec), metadata, batch);
}

void write_pixels(const std::string& path, ImageWrite w, const ImageMetadata& metadata) {
    write_atomically(path, std::move(w), metadata, nullptr);
}

Image read_float_image(const std::string& path, bool* has_alpha) {
    std::string why;
    std::unique_ptr<ImageReader> in = image_library().open(path, {}, &why);
    if (!in) {
        throw Error(ErrorKind::MissingFile, {},
                    "cannot read " + path + (why.empty() ? std::string() : ": " + why));
    }
    const ImageHeader& spec = in->header();
    if (!is_float_pixel(spec.type))
        throw Error(ErrorKind::Usage, {},
                    path +
                        " is not a float image: give a linear .exr or .hdr (an 8/16-bit "
                        "file is already display-encoded)");
    const int nc = spec.channels;
    if (spec.width <= 0 || spec.height <= 0 || nc <= 0)
        throw Error(ErrorKind::MissingFile, {}, "cannot read " + path + ": the image is empty");
    const size_t pixels = static_cast<size_t>(spec.width) * spec.height;
    std::vector<float> data(pixels * nc);
    why = in->read(nc, data.data());
    if (!why.empty()) throw Error(ErrorKind::MissingFile, {}, "cannot read " + path + ": " + why);
    const int alpha = spec.alpha_channel >= 0 ? spec.alpha_channel : (nc == 4 ? 3 : -1);
    if (has_alpha) *has_alpha = alpha >= 0;
    Image image;
    image.width = spec.width;
    image.height = spec.height;
    image.rgba.resize(pixels * 4);
    for (size_t i = 0; i < pixels; ++i) {
        const float* p = &data[i * nc];
        float* q = &image.rgba[i * 4];
        for (int c = 0; c < 3; ++c) q[c] = nc >= 3 ? p[c] : p[0];
        q[3] = alpha >= 0 ? p[alpha] : 1.0f;
    }
    return image;
}

}  // namespace glint::io
