// Where in and around its pixel a path tracer's camera sample lands. glint's own filter is a
// box over the pixel; Blender scenes bring Cycles' (Box, Gaussian, Blackman-Harris with a
// width in pixels), which Cycles importance-samples: every sample has weight 1 and its offset
// follows the filter's shape (film.cpp's filter table). The offset is per axis.
#pragma once

#include <vector>

namespace glint::render {

enum class PixelFilterKind { GlintBox, Box, Gaussian, BlackmanHarris };

class PixelFilter {
public:
    PixelFilter() = default;
    PixelFilter(PixelFilterKind kind, double width);
    // The offset from the pixel's centre, in pixels, for u in [0, 1).
    double offset(double u) const;

private:
    PixelFilterKind kind_ = PixelFilterKind::GlintBox;
    double half_ = 0.5;         // support: [-half_, half_]
    std::vector<double> cdf_;   // over the support, kTable bins (Gaussian, Blackman-Harris)
};

}  // namespace glint::render
