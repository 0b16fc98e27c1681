// The palette indices of a GIF's first image, undecoded to colours: POV-Ray's .pot height
// fields (Fractint's continuous potential files) keep 16-bit heights in them, the left half of
// the image holding the high bytes and the right half the low bytes (POV-Ray's gif.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace glint {

struct GifIndices {
    int width = 0, height = 0;
    std::vector<uint8_t> index;  // width * height, row 0 (the top row) first
};

// Reads `path`; on failure returns false with a one-line reason in `error`. Interlaced images
// are refused, as POV-Ray does.
bool read_gif_indices(const std::string& path, GifIndices* out, std::string* error);

}  // namespace glint
