// User-defined functions as patterns: an expression with parameters and built-ins, a call of
// functions.inc's internal f_noise3d, a spline-driven color, and a pattern function.
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at <0, 0, 0> angle 50 }
light_source { <-10, 10, -10>, rgb 1 }
#declare Ring = function(a, b, k) { sin(k * sqrt(a * a + b * b)) * 0.5 + 0.5 }
#declare Mix = function { select(x, Ring(x, y, 8), 0.5 * f_noise3d(x * 3, y * 3, z * 3) + 0.25) }
#declare Agate = function { pattern { agate scale 0.5 } }
#declare Path = spline { natural_spline -2, <0.2, 0, 0> 0, <1, 0.5, 0> 2, <0, 0.3, 1> }
plane { z, 0
  pigment { function { Mix(x, y, z) } color_map { [0 rgb <0.1, 0.1, 0.3>] [1 rgb <1, 0.9, 0.6>] } }
  finish { ambient 0.2 diffuse 0.8 }
  clipped_by { box { <-3, -2, -1>, <0.5, 2, 1> } }
}
box { <0.6, -2, -0.5>, <1.6, 2, 0.5>
  pigment { function { Agate(x, y, z) } color_map { [0 rgb 0] [1 rgb <0.8, 0.3, 0.2>] } }
}
#declare I = -2;
#while (I <= 2)
  sphere { <2.3, I, 0>, 0.3 pigment { rgb Path(I) } }
  #declare I = I + 0.5;
#end
