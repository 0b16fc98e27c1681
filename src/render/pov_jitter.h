// POV-Ray 3.7's position-hashed jitter (backend/support/jitter.h, Jitter2d for real
// coordinates): two offsets in [-0.5, 0.5] for a raster position, from POV-Ray's noise hash of
// the coordinates scaled by the primes 1019 and 1021. It moves anti-aliasing sub-samples and
// focal blur's aperture points; being a function of the position alone, the image does not
// depend on which thread traces a pixel.
#pragma once

namespace glint::render {

void pov_jitter2d(double x, double y, double* jx, double* jy);

}  // namespace glint::render
