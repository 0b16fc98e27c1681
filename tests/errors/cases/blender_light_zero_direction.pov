#version 3.7;
global_settings { assumed_gamma 1 }
blender_light { sun direction <0, 0, 0> }
