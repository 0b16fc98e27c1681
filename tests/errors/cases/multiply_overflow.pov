#version 3.7;
global_settings { assumed_gamma 1 }
#declare Big = 1e300 * 1e300;
