// A BSSRDF at a shading point: light that enters the surface, scatters inside and leaves it
// elsewhere (Blender's Principled subsurface and Subsurface Scattering node), as Cycles 3.4
// sets it up (kernel/closure/bssrdf.h). It is not a BSDF: it adds nothing to light sampling
// where it is, and a path that picks it walks through the object (render/media/subsurface.h)
// and goes on from where the walk leaves.
#pragma once

#include "core/math.h"

namespace glint::render {

struct Bssrdf {
    Color weight;  // the closure's weight, its albedo included
    // Per channel, the random walk's mean free path (scene units) after setup(); 0 where the
    // channel's radius was too small to walk (that part is diffuse).
    Color radius;
    Color albedo;             // the surface colour the walk should come out with
    double anisotropy = 0;    // Henyey-Greenstein g inside, [0, 0.9]
    bool exit_fresnel = false;  // Principled: the exit lobe has Burley's Fresnel
    Vec3 n;                   // the closure's normal, on the viewer's side
    int channels = 0;         // channels left to walk

    // Cycles' bssrdf_setup: channels whose radius is under 1e-8 leave the BSSRDF, their
    // weight returned in *diffuse (for a diffuse lobe in its place); the radius of the others
    // becomes the walk's mean free path: scaled by 1 / (4 pi) when `fixed_radius` (Random
    // Walk (Fixed Radius), Christensen-Burley), else by sqrt(3 (1 - a')) where a' is the
    // single-scattering albedo whose diffusion reflectance (Jensen's dipole with the boundary
    // term of `ior`) is the surface albedo. Returns the channels left.
    int setup(bool fixed_radius, double ior, Color* diffuse);
    // Its share of the closure samples (Cycles: |average weight| x channels).
    double sample_weight() const;
};

}  // namespace glint::render
