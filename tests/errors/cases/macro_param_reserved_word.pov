#version 3.7;
global_settings { assumed_gamma 1 }
#macro Shift(Obj, x)
    object { Obj translate x }
#end
