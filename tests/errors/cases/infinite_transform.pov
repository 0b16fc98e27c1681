#version 3.7;
global_settings { assumed_gamma 1 }
sphere { 0, 1 pigment { rgb 1 } scale 1e200 scale 1e200 }
