// Writing the film to a file through OpenImageIO: format from the extension (png, exr, tif,
// hdr, jpg), color encoding through OpenColorIO for display-referred formats, and an atomic
// write (temporary name, then rename) so a failed write never leaves a partial file.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "image/image_library.h"
#include "image/image.h"

namespace glint::io {

// How film values become file values.
//
// Film values live in the scene's working space: linear when working_gamma is 1 (POV-Ray 3.7
// with assumed_gamma 1), power-law encoded with working_gamma otherwise (assumed_gamma 2.2
// makes POV-Ray light the raw 0..1 numbers as they are), or sRGB-encoded for legacy scenes
// (working_srgb: POV-Ray sets the working gamma to the display gamma). 8/16-bit formats get
// transfer(decode_working(v)); float formats (exr, hdr) get decode_working(v), i.e. linear
// light, and need no color transform at all when the working space is linear. This is POV-Ray
// 3.7's TranscodingGammaCurve (source/base/image/colourspace.cpp), including its shortcut: a
// working space equal to the transfer is the identity.
//
// ViewSettings (glint's --view, --look, --exposure, --gamma): Blender's Color Management panel.
// With a view the 8/16-bit file gets what Blender 3.4 saves for the linear image (the float
// formats' values) through its OpenColorIO config, instead of POV-Ray's encoding.
struct ViewSettings {
    std::string view;       // a view of `display` ("Standard", "Filmic"); empty: no view
    std::string look;       // empty or "None": no look
    float exposure = 0.0f;  // EV; Blender keeps these two as floats
    float gamma = 1.0f;
    std::string display = "sRGB";
    std::string config_path;  // config.ocio; empty: find_ocio_config (color_encoding.h)

    bool active() const { return !view.empty(); }
};

struct OutputEncoding {
    enum class Transfer { Linear, Srgb, Gamma } transfer = Transfer::Srgb;
    double gamma = 2.2;          // Transfer::Gamma: file value = v^(1/gamma)
    double working_gamma = 1.0;  // film value v is linear after v^working_gamma
    bool working_srgb = false;   // film values are sRGB-encoded (overrides working_gamma)
    bool alpha = false;          // write an alpha channel (POV-Ray +UA)
    ViewSettings view;           // when active, replaces the transfer for 8/16-bit files
};

// The OpenImageIO format name for the path's extension (case-insensitive): png, openexr,
// tiff, hdr, jpeg. Throws Error(Output) "unsupported output format" for anything else, so the
// CLI can refuse a bad name before it renders.
std::string output_format_for(const std::string& path);

// Whether the path's format stores linear float values (exr, hdr). Throws like
// output_format_for.
bool is_float_format(const std::string& path);

// Text stored in the file's header as (name, value) string attributes: PNG text chunks, EXR
// header attributes, TIFF/JPEG where OpenImageIO maps the name (ImageDescription always).
using ImageMetadata = std::vector<std::pair<std::string, std::string>>;

// Files that appear together or not at all (an image and its AOV/variance side files): writers
// given a batch leave their file under its temporary name; commit() renames them all into
// place. A batch destroyed without commit() removes its temporaries.
class OutputBatch {
public:
    OutputBatch() = default;
    ~OutputBatch();
    OutputBatch(const OutputBatch&) = delete;
    OutputBatch& operator=(const OutputBatch&) = delete;
    // Throws Error(Output) when a rename fails; the files renamed before it stay.
    void commit();
    void add(std::string temp, std::string path) { staged_.emplace_back(std::move(temp), std::move(path)); }

private:
    std::vector<std::pair<std::string, std::string>> staged_;  // temporary, final path
};

// Throws Error(Output) ("cannot write PATH: ...") unless a file can be created beside `path`
// under its temporary name: the folder exists and is writable, `path` is not a folder. Creates
// and removes that file, so it leaves nothing behind. For checks before a long render.
void check_writable(const std::string& path);

// Throws glint::Error(ErrorKind::Output) naming the path and the reason. Writes
// `<path>.tmp-<pid>` beside the target and renames it; on failure the temporary is removed.
// PNG and JPEG get 8 bits, TIFF 16 bits per channel, EXR and HDR 32-bit float. With a batch
// the rename waits for batch->commit().
void write_image(const Image& image, const std::string& path,
                 const OutputEncoding& encoding, const ImageMetadata& metadata = {},
                 OutputBatch* batch = nullptr);

// Writes the first `channels` of the image (1 or 3) as a 32-bit float OpenEXR file, values as
// they are (no encoding): the path tracer's AOVs and variance. One channel is named Z
// (OpenEXR's depth channel), three R, G, B. Atomic like write_image; throws Error(Output).
void write_float_exr(const Image& image, const std::string& path, int channels = 3,
                     const ImageMetadata& metadata = {}, OutputBatch* batch = nullptr);

// Writes pixels that are already in the file's own type and encoding (w.data, w.type: glint
// merge joins parts without decoding or encoding them again), atomically like write_image.
// w.path is ignored; w.format must be an OpenImageIO writer name. Throws Error(Output).
void write_pixels(const std::string& path, ImageWrite w, const ImageMetadata& metadata);

// Reads a float image (OpenEXR, Radiance HDR) as linear RGBA: one channel becomes gray, a
// missing alpha 1; `has_alpha` tells whether the file had one. Throws Error(MissingFile) when
// it cannot be read and Error(Usage) for an integer (display-encoded) file.
Image read_float_image(const std::string& path, bool* has_alpha = nullptr);

}  // namespace glint::io
