#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -3> look_at 0 angle 180 }
sphere { 0, 1 }
