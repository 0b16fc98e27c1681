#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, 0> look_at <0, 0, 0> }
sphere { 0, 1 pigment { rgb 1 } }
