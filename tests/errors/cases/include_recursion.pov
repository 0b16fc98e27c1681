#version 3.7;
global_settings { assumed_gamma 1 }
#include "include_recursion.pov"
