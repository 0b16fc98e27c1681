#version 3.7;
global_settings { assumed_gamma 1 }
#declare I = 0;
#while (I < 3)
    sphere { <I, 0, 0>, 0.5 }
    #declare I = I + 1;
