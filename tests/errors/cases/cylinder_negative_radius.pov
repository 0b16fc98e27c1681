#version 3.7;
global_settings { assumed_gamma 1 }
cylinder { 0, y, -0.5 pigment { rgb 1 } }
