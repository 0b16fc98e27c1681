#version 3.7;
global_settings { assumed_gamma 1 }
#declare Radius = 2;
sphere { Center, Radius pigment { rgb 1 } }
