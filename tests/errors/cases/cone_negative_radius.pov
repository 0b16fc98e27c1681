#version 3.7;
global_settings { assumed_gamma 1 }
cone { 0, 1, y, -0.5 pigment { rgb 1 } }
