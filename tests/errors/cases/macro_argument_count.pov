#version 3.7;
global_settings { assumed_gamma 1 }
#macro Ball(Center)
    sphere { Center, 1 }
#end
Ball(<0, 0, 0>, 2)
