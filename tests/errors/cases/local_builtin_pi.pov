#version 3.7;
global_settings { assumed_gamma 1 }
#macro Radius_Of(R)
    #local pi = 3.14;
    R * pi
#end
sphere { 0, Radius_Of(1) }
