// PNG encoding with libpng, for the renders that need no more: 8- or 16-bit RGB, no alpha. It
// keeps OpenImageIO (image/image_library.h) out of the process for the most common output;
// PNGs with alpha and every other format still go through OpenImageIO.
#pragma once

#include <string>
#include <vector>

#include "image/image_library.h"

namespace glint {

// Whether encode_png() takes this request.
bool png_writer_accepts(const ImageWrite& w);

// Encodes w (data rows top to bottom, w.type UInt8 or UInt16) into *bytes. Attributes:
// oiio:ColorSpace "sRGB" writes the sRGB, gAMA and cHRM chunks, "Linear" gAMA 1;
// oiio:Gamma g (without a colour space) gAMA 1/g; ImageDescription a Description text chunk
// and any other string attribute a text chunk of its own name. Returns the reason it failed,
// empty on success.
std::string encode_png(const ImageWrite& w, std::vector<unsigned char>* bytes);

}  // namespace glint
