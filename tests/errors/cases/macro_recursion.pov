#version 3.7;
global_settings { assumed_gamma 1 }
#macro Forever(N)
    Forever(N + 1)
#end
Forever(0)
