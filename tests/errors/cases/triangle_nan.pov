#version 3.7;
global_settings { assumed_gamma 1 }
triangle { <0,0,0>, <1,0,0>, <0,1,1e300*1e300> pigment { rgb 1 } }
