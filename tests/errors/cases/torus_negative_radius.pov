#version 3.7;
global_settings { assumed_gamma 1 }
torus { 1, -0.25 pigment { rgb 1 } }
