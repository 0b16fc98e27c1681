#version 3.7;
global_settings { assumed_gamma 1 }
#declare S = "0123456789";
#while (1)
    #declare S = concat(S, S);
#end
