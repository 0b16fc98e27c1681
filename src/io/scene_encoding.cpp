#include "io/scene_encoding.h"

namespace glint::io {

OutputEncoding output_encoding_for(const scene::Scene& scene) {
    OutputEncoding e;
    e.transfer = OutputEncoding::Transfer::Srgb;
    if (scene.global.assumed_gamma) {
        e.working_gamma = *scene.global.assumed_gamma;
    } else if (static_cast<int>(scene.version * 100 + 0.5) < 370) {  // as POV-Ray rounds it
        // POV-Ray sets both the working and the file gamma to the display gamma (sRGB), so
        // the transcoding between them is the identity for 8-bit files.
        e.working_srgb = true;
    } else {
        e.working_gamma = 1.0;
    }
    return e;
}

}  // namespace glint::io
