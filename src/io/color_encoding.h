// Turning linear (or working-gamma) film values into display-encoded values for 8/16-bit
// files: the transfer function through OpenColorIO, then POV-Ray 3.7's quantization. Used by
// image_output (writing) and image_compare (float images compared in 8-bit space).
#pragma once

#include <cstdint>
#include <vector>

#include "io/image_output.h"
#include "render/image.h"

namespace glint::io {

// Encodes the RGB of every pixel for an 8/16-bit file: returns width*height*3 encoded values
// in [0, 1] (clamped; NaN becomes 0). Alpha is not touched here. Builds OpenColorIO
// processors from transforms in code; no configuration file is read. Throws Error(Output) when
// OpenColorIO rejects the transform.
std::vector<float> encode_rgb(const render::Image& image, const OutputEncoding& encoding);

// POV-Ray 3.7's quantization (source/base/image/encoding.h, IntEncode): clip to [0, 1],
// scale by max, add one half, floor, all in single precision; no dithering (POV-Ray's
// default, Dither=off).
inline unsigned quantize(float encoded, unsigned max) {
    float v = encoded;
    if (!(v > 0.0f)) v = 0.0f;  // also catches NaN
    if (v > 1.0f) v = 1.0f;
    return static_cast<unsigned>(v * static_cast<float>(max) + 0.5f);
}

// The film as linear light for float formats (exr, hdr): RGB decoded from the working space,
// alpha unchanged, NaN made 0 and infinities the largest float. Width*height*4 values. Touches
// OpenColorIO only when the working space is not linear.
std::vector<float> linear_rgba(const render::Image& image, const OutputEncoding& encoding);

// The encoded value of one film value; convenient for tests and single colors.
float encode_value(float value, const OutputEncoding& encoding);

}  // namespace glint::io
