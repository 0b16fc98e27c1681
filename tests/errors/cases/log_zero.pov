#version 3.7;
global_settings { assumed_gamma 1 }
sphere { 0, ln(0) pigment { rgb 1 } }
