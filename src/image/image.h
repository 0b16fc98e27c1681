// The film's result: linear, scene-referred RGBA in float, top row first. Color management and
// encoding happen only in src/io.
#pragma once

#include <vector>

namespace glint {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<float> rgba;  // width * height * 4

    float* pixel(int x, int y) { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
    const float* pixel(int x, int y) const {
        return &rgba[(static_cast<size_t>(y) * width + x) * 4];
    }
};

}  // namespace glint
