// media_atmosphere: atmospheric media everywhere (outside non-hollow objects): spotlight and
// cylinder-light beams made visible by Mie murky scattering, with shadows cut through them,
// a light that stays out of the media (media_interaction off) and one dimmed by them on the
// way (media_attenuation on). A glass sphere (not hollow) holds no media; a hollow one does.
// A dark hollow room bounds the rays (a ray to infinity would gather light without end).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 1.5, 0> angle 55 }
background { rgb 0.02 }
media {
  scattering { 3, rgb 0.05 }
  absorption 0.01
  intervals 6
  samples 3, 3
}
light_source { <-2, 7, 1> rgb <1.3, 1.2, 1> spotlight point_at <-1, 0, 0> radius 10 falloff 16 }
light_source { <5, 4, 2> rgb <0.4, 0.6, 1.2> cylinder point_at <-4, 0.5, 0> radius 0.6
               falloff 0.9 }
light_source { <0, 8, -8> rgb 0.35 media_interaction off }
light_source { <6, 6, -4> rgb <0.5, 0.3, 0.2> media_attenuation on }
plane { y, 0 pigment { rgb 0.7 } }
box { <-1.4, 2.5, -0.2> <-0.7, 2.7, 0.5> pigment { rgb <0.2, 0.8, 0.3> } }
sphere { <1.8, 1, 0> 1 pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.3 } }
sphere { <-3, 0.8, -1> 0.8 pigment { rgbt 1 } hollow }
box { <-20, -1, -20> <20, 15, 20> pigment { rgb 0.05 } hollow }
