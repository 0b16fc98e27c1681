// The random walk under a surface that a BSSRDF (render/bsdf/bssrdf.h) stands for, as Cycles
// 3.4 walks it (kernel/integrator/subsurface_random_walk.h): the surface albedo becomes a
// homogeneous medium's single-scattering albedo and extinction (the fits of Chiang, Kutz and
// Burley 2016, extended to anisotropic phase functions by Wrenninge, Villemin and Hery 2017),
// and the path scatters through it until it crosses the object's surface again. Each step
// picks its colour channel by throughput x albedo (one-sample spectral MIS) and its direction
// by the phase function or by Dwivedi's guiding towards the surface it entered (or the
// opposite one when a first probe found it near), all weighed by the balance heuristic
// (Meng, Hanika and Dachsbacher 2016; d'Eon and Krivanek 2020). After nine bounces the walk
// turns isotropic with the similarity relation. It sees its own object only.
#pragma once

#include <cstdint>
#include <functional>

#include "render/bsdf/bssrdf.h"
#include "render/prepare/geometry.h"

namespace glint::render {

// Cycles' walk limits.
constexpr int kSubsurfaceMaxBounces = 256;

// The medium the walk goes through for one channel: the surface albedo and the mean free
// path `d` into extinction sigma_t and single-scattering albedo alpha, for HG anisotropy g.
void subsurface_coefficients(double albedo, double d, double g, double* sigma_t,
                             double* alpha);

// Walks from `entry` into its object, seen along `wo` (towards the viewer): `b` the BSSRDF
// set up there, `beta` the path's throughput with the BSSRDF's sample weight applied, `random`
// numbers in
// [0, 1). On success the hit where the walk leaves, the direction it leaves along (out of the
// surface) and the throughput there; false when the walk is lost (too many bounces, absorbed,
// never leaves). `rays` counts the rays cast.
bool subsurface_walk(const Geometry& geometry, const Bssrdf& b, const Hit& entry,
                     const Vec3& wo, const std::function<double()>& random, Color* beta, Hit* exit,
                     Vec3* exit_dir, uint64_t* rays);

}  // namespace glint::render
