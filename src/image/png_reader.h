// PNG files read through libpng directly, for image maps and height fields: loading the
// OpenImageIO module costs about 350 ms (image/image_library.h), more than a scene with one
// small PNG texture takes to render. The reader gives what OpenImageIO's PNG reader gives
// (tests/unit/png_reader_test.cpp holds the two side by side): low bit depths, palettes and
// tRNS expanded to 8-bit channels with alpha, 16-bit kept, oiio:ColorSpace "sRGB" unless a
// gAMA chunk without sRGB says otherwise ("linear", or "GammaX.Y" with the gamma rounded to a
// hundredth), alpha left unassociated.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "image/image_library.h"

namespace glint {

// The PNG at `path` when libpng alone can give what OpenImageIO would: the file starts with
// PNG's signature, and its alpha, if any, is to stay unassociated. Null otherwise, with
// *error empty when the caller should ask OpenImageIO instead, or saying why the PNG cannot be
// read.
std::unique_ptr<ImageReader> open_png(const std::string& path, bool keep_unassociated_alpha,
                                      std::string* error);

// An image file for reading: PNGs through open_png() where it can, everything else through
// image_library() (`config` as there). A PNG read by open_png() has no text in its header (its
// tEXt chunks are not read): for images whose pixels are all that is used.
std::unique_ptr<ImageReader> open_image(const std::string& path,
                                        const std::vector<std::pair<std::string, int>>& config,
                                        std::string* error);

}  // namespace glint
