// VALIDATION.md case 14 (Whitted): a dark floor with a Phong highlight of exponent Size
// (#declare'd by the test) under a point light. Camera and light are mirror images across the
// floor's normal through the look_at point, so the highlight's centre (the mirror point) is
// the origin, which the centre pixel's ray hits exactly.
#ifndef (Size) #declare Size = 40; #end
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2, -3> look_at <0, 0, 0> angle 40 }
light_source { <0, 4, 6> color rgb 1 }
background { color rgb 0 }

plane { y, 0 pigment { color rgb 0.2 } finish { ambient 0 diffuse 0.2 phong 1 phong_size Size } }
