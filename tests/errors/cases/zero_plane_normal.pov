#version 3.7;
global_settings { assumed_gamma 1 }
plane { <0, 0, 0>, 1 pigment { rgb 1 } }
