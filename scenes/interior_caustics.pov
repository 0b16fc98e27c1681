// POV-Ray's fake caustics (interior { caustics C }): shadow rays through a transparent
// object are brightened by 1 + |n . d|^C, so glass gathers light where it faces the lamp.
// Two glass spheres (caustics 1 and 0.3, one with bumps) and a clear box without caustics.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.3, 0> angle 50 }
light_source { <-3, 9, -4> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.85 rgb 0.6 scale 0.8 } }
sphere { <-1.6, 0, 0>, 1
  pigment { rgbf <0.95, 0.98, 1, 0.95> }
  finish { ambient 0 diffuse 0.05 phong 0.8 }
  interior { ior 1.5 caustics 1 } }
sphere { <0.9, 0, 0.4>, 1
  pigment { rgbf <1, 0.9, 0.7, 0.9> }
  normal { bumps 0.4 scale 0.3 }
  finish { ambient 0 diffuse 0.05 }
  interior { ior 1.33 caustics 0.3 } }
box { <2.2, -1, -1.8>, <3.2, 0.5, -0.8>
  pigment { rgbt <0.8, 1, 0.8, 0.8> }
  interior { ior 1.2 } }
