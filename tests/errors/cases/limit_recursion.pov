#version 3.7;
global_settings { assumed_gamma 1 }
#macro Deep(N)
    #if (N > 0) Deep(N - 1) #end
#end
Deep(100)
