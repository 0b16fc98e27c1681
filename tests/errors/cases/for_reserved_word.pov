#version 3.7;
global_settings { assumed_gamma 1 }
#for (clock, 0, 3)
    sphere { <clock, 0, 0>, 0.4 }
#end
