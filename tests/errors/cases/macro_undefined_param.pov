#version 3.7;
global_settings { assumed_gamma 1 }
#macro M(A)
    sphere { 0, B }
#end
M(1)
