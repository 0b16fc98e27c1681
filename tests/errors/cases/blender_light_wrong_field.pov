#version 3.7;
global_settings { assumed_gamma 1 }
blender_light { sun radius 0.5 }
