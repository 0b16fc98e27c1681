#version 3.7;
global_settings { assumed_gamma 1 }
#include "no_such_file.inc"
sphere { 0, 1 }
