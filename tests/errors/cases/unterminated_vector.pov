#version 3.7;
global_settings { assumed_gamma 1 }
sphere { <1, 2, 1 pigment { rgb 1 } }
