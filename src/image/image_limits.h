// Input images (image_map, height_field) are read whole into floats, and a picture's header can
// claim any size: a PNG of a few bytes saying 100000 x 100000 would have glint allocate 160 GB
// before reading one pixel. The size is bounded first.
#pragma once

#include <string>

#include "core/error.h"

namespace glint {

// 16384 x 16384, the default of --max-image-pixels for the output.
constexpr long long kMaxInputImagePixels = 1LL << 28;

inline void check_image_size(int width, int height, int channels, const std::string& name,
                             const FileLoc& at) {
    if (static_cast<long long>(width) * height > kMaxInputImagePixels || channels > 64)
        throw Error(ErrorKind::Render, at,
                    "image '" + name + "' is " + std::to_string(width) + " x " +
                        std::to_string(height) + " pixels with " + std::to_string(channels) +
                        " channels, more than glint reads (" +
                        std::to_string(kMaxInputImagePixels) + " pixels, 64 channels)");
}

}  // namespace glint
