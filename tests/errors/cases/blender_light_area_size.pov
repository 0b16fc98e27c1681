#version 3.7;
global_settings { assumed_gamma 1 }
blender_light { area shape rectangle size <1, -1> }
