#version 3.7;
global_settings { assumed_gamma 1 }
#macro Ball(R)
    sphere { 0, R * Missing }
#end
Ball(1)
