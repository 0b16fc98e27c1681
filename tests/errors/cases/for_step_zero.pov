#version 3.7;
global_settings { assumed_gamma 1 }
#for (I, 0, 10, 0)
#end
