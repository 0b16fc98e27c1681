#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -3> right 0 look_at 0 }
sphere { 0, 1 }
