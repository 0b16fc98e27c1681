#version 3.7;
global_settings { assumed_gamma 1 }
#declare A = array[2] { 1, 2, 3 }
