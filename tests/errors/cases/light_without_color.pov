#version 3.7;
global_settings { assumed_gamma 1 }
light_source { <0, 5, -5> }
