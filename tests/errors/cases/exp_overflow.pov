#version 3.7;
global_settings { assumed_gamma 1 }
sphere { 0, exp(1000) pigment { rgb 1 } }
