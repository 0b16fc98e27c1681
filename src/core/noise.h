// POV-Ray 3.7's solid noise (backend/texture/texture.cpp): the lattice noise Noise()/DNoise()
// with its hash and RTable tables, Perlin's gradient noise (noise_generator 3) and the fBm sums
// Turbulence()/DTurbulence(). Used by the pattern evaluator (render/textures/pattern.cpp) and by
// the SDL's vturbulence()/f_noise3d at parse time, so it lives in core and sees no scene type.
// The tables are built once (thread-safe static initialisation); every call is allocation-free.
#pragma once

#include "core/math.h"

namespace glint {

// POV-Ray's TURB parameters, as plain values (scene::Turbulence carries the same fields).
struct TurbulenceParams {
    int octaves = 6;
    double omega = 0.5;
    double lambda = 2.0;
};

// POV-Ray's Noise(EPoint, noise_generator), in [0, 1]. generator: 1 = the original (pre-3.5)
// range, 2 = range-corrected (3.7's default), 3 = Perlin gradient noise. Any other value
// behaves as 1 (POV-Ray tests `== 2` and `== 3`).
double noise(const Vec3& p, int generator);

// POV-Ray's DNoise(): a vector-valued noise, each component roughly in [-1, 1]. It has no
// generator: POV-Ray 3.7 uses the lattice noise for every noise_generator.
Vec3 dnoise(const Vec3& p);

// POV-Ray's Turbulence(EPoint, Turb, noise_generator): fBm of `octaves` noise calls at
// frequencies lambda^i and weights omega^i. Not clamped (can exceed 1 for generator 1).
double turbulence(const Vec3& p, const TurbulenceParams& turb, int generator);

// POV-Ray's DTurbulence(): the vector fBm sum of dnoise. The caller scales it by the
// turbulence amount (per axis) as POV-Ray's warps do.
Vec3 dturbulence(const Vec3& p, const TurbulenceParams& turb);

// POV-Ray's Hash3d(a, b, c) over the same permutation table (texture.h): a value in 0..4095
// for the low 12 bits of each lattice coordinate. Used by the cell patterns (cells, crackle,
// facets) and the black_hole warp.
int hash3d(int a, int b, int c);
// One entry of that table: POV-Ray's hashTable[i & 0xfff], which its jitter (Jitter2d) and
// focal blur (PseudoRandom) index directly.
int noise_hash(int i);

// POV-Ray's PatternRands(seed) / WarpRands(seed): a fixed sequence of 32768 uniform numbers in
// [0, 1) (boost's mt19937 with its default seed through uniform_real), indexed modulo 32768.
double pattern_random(unsigned seed);

}  // namespace glint
