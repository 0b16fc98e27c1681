// Which output encoding a POV-Ray scene asks for: POV-Ray 3.7's gamma rules (assumed_gamma and
// #version) turned into an OutputEncoding. Used by `glint render`; docs/output-encoding.md
// records the experiments that established the rules.
#pragma once

#include "io/image_output.h"
#include "scene/scene.h"

namespace glint::io {

// POV-Ray 3.7 with its default File_Gamma (sRGB) and Display_Gamma (sRGB):
// - assumed_gamma G given (any #version): film values are in a power-law working space with
//   gamma G; the file gets sRGB(v^G). G within 1% of 1 counts as linear.
// - no assumed_gamma, #version >= 3.7: as assumed_gamma 1.0 (sRGB of the linear value).
// - no assumed_gamma, #version < 3.7 (also a scene without #version, which POV-Ray reads as
//   3.62): gamma handling off: POV-Ray's working and file gammas are both the display gamma
//   (sRGB), so a PNG gets the film value unchanged and an EXR gets its sRGB decoding.
// (source/backend/parser/parse.cpp post-parse gamma defaults; source/frontend/renderfrontend.h
// CreateView; source/frontend/imageprocessing.cpp.)
OutputEncoding output_encoding_for(const scene::Scene& scene);

}  // namespace glint::io
