// Turning linear (or working-gamma) film values into display-encoded values for 8/16-bit
// files: the transfer function through OpenColorIO, then POV-Ray 3.7's quantization. Used by
// image_output (writing) and image_compare (float images compared in 8-bit space).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/image_output.h"
#include "image/image.h"

namespace glint::io {

// Encodes the RGB of every pixel for an 8/16-bit file: returns width*height*3 encoded values
// in [0, 1] (clamped; NaN becomes 0). Alpha is not touched here. Builds OpenColorIO
// processors from transforms in code; no configuration file is read. Throws Error(Output) when
// OpenColorIO rejects the transform.
std::vector<float> encode_rgb(const Image& image, const OutputEncoding& encoding);

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
std::vector<float> linear_rgba(const Image& image, const OutputEncoding& encoding);

// The encoded value of one film value; convenient for tests and single colors.
float encode_value(float value, const OutputEncoding& encoding);

// --- Blender's view transforms (ViewSettings, --view) ---
//
// Blender 3.4 saves a float image as PNG/JPEG like this (imbuf color management): exposure
// (a scale of 2^EV in scene linear), the look, the display's view transform (Standard: the
// sRGB curve, Filmic: its log shaper and LUTs, all from config.ocio), gamma (an exponent of
// 1/G), built as one OpenColorIO GroupTransform and run by the processor's default CPU
// processor; pixels with alpha strictly between 0 and 1 are divided by alpha before the
// transform and multiplied after it (Blender's premultiplied float buffers), then divided
// again for the file's straight alpha; finally unit_float_to_uchar_clamp, which for every
// non-NaN value equals `quantize` above (clip, * 255, + 0.5, truncate). A 16-bit TIFF keeps
// the premultiplied display values (TIFF's associated alpha) and unit_float_to_ushort_clamp.
// glint builds the same transforms with the same OpenColorIO (Debian's 2.1, which Debian's
// Blender links), so the floats, and the 8/16-bit codes, are the same.

// The config.ocio to use: `given` when not empty, else $OCIO, else Blender's own
// (/usr/share/blender/datafiles/colormanagement/config.ocio, then the versioned
// /usr/share/blender/<version>/datafiles/colormanagement/config.ocio, newest first, then the
// same under /usr/local/share/blender). Throws Error(MissingFile) naming every place searched.
std::string find_ocio_config(const std::string& given);

// Checks the view, display and look against the config (Error(Usage) listing the valid names)
// and returns the settings with config_path resolved.
ViewSettings resolve_view(const ViewSettings& view);

// `rgba`: width*height*4 linear values, premultiplied alpha (as OpenEXR stores them and as
// Blender holds a render). Returns the display values, unclamped (quantize clips them), with
// straight alpha (8-bit files) or premultiplied (`straight` false: Blender's 16-bit TIFF).
// Loads the config once per call; throws Error(Output) when OpenColorIO fails.
std::vector<float> view_rgba(const std::vector<float>& rgba, int width, int height,
                             const ViewSettings& view, bool straight = true);

// Blender's unit_float_to_ushort_clamp: 65535 from 1 - 0.5/65535 up, 0 from 0 down (and NaN),
// else truncate(v * 65535 + 0.5).
inline unsigned quantize_blender16(float v) {
    if (v >= 1.0f - 0.5f / 65535.0f) return 65535;
    if (!(v > 0.0f)) return 0;
    return static_cast<unsigned>(v * 65535.0f + 0.5f);
}

// One line for -v: "view Filmic, look None, exposure 0, gamma 1 (display sRGB, CONFIG)".
std::string describe_view(const ViewSettings& view);

}  // namespace glint::io
