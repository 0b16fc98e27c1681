#version 3.7;
global_settings { assumed_gamma 1 }
#declare T = texture { pigment { rgb 1 } }
sphere { 0, T }
