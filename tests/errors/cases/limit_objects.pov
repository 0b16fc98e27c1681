#version 3.7;
global_settings { assumed_gamma 1 }
#for (I, 1, 100)
    sphere { <I, 0, 0>, 0.5 }
#end
