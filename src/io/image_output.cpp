#include "io/image_output.h"

#include "core/error.h"

namespace glint::io {
void write_image(const render::Image&, const std::string& path, const OutputEncoding&) {
    throw Error(ErrorKind::Output, {}, "image output not written yet: " + path);
}
}  // namespace glint::io
