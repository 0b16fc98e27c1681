#version 3.7;
global_settings { assumed_gamma 1 }
#declare I = 0;
#while (1)
    #declare I = I + 1;
#end
