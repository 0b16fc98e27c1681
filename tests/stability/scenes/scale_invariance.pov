// VALIDATION.md case 1: a sphere on a plane under a point light, scaled by S and moved by T
// (both #declare'd by the test before this file is read). Nothing in the scene depends on the
// absolute scale (no light fading, no fixed distances), so every S and T must give the same
// image. The plane and the sphere are plain colours so that the test can shade them
// analytically (acne check).
#ifndef (S) #declare S = 1; #end
#ifndef (T) #declare T = <0, 0, 0>; #end
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2, -6> * S + T look_at <0, 0.8, 0> * S + T angle 50 }
light_source { <-3, 6, -4> * S + T color rgb 1 }
background { color rgb <0.1, 0.1, 0.2> }

plane { y, 0 pigment { color rgb <0.8, 0.8, 0.8> } finish { ambient 0.1 diffuse 0.6 }
        translate T }
sphere { <0, 1, 0> * S + T, S pigment { color rgb <0.9, 0.3, 0.2> }
         finish { ambient 0.1 diffuse 0.6 } }
