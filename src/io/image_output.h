// Writing the film to a file through OpenImageIO: format from the extension (png, exr, tif,
// hdr, jpg), color encoding through OpenColorIO for display-referred formats, and an atomic
// write (temporary name, then rename) so a failed write never leaves a partial file.
#pragma once

#include <string>

#include "render/image.h"

namespace glint::io {

// How linear film values become file values for 8/16-bit formats. Float formats (exr, hdr)
// always get linear values and never load a color configuration.
struct OutputEncoding {
    enum class Transfer { Linear, Srgb, Gamma } transfer = Transfer::Srgb;
    double gamma = 2.2;  // Transfer::Gamma
    bool alpha = false;  // write an alpha channel (POV-Ray +UA)
};

// Throws glint::Error(ErrorKind::Output) naming the path and the reason.
void write_image(const render::Image& image, const std::string& path,
                 const OutputEncoding& encoding);

}  // namespace glint::io
