#version 3.7;
global_settings { assumed_gamma 1 }
#declare Name = "no closing quote;
sphere { 0, 1 }
