#version 3.7;
global_settings { assumed_gamma 1 }
#declare V = vnormalize(<0, 0, 0>);
