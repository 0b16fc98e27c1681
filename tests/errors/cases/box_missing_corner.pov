#version 3.7;
global_settings { assumed_gamma 1 }
box { <0, 0, 0> }
