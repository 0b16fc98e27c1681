#version 3.7;
global_settings { assumed_gamma 1 }
cylinder { <1, 2, 3>, <1, 2, 3>, 0.5 pigment { rgb 1 } }
