#version 3.7;
global_settings { assumed_gamma 1 }
sphere { 0, <1, 2, 3> pigment { rgb 1 } }
