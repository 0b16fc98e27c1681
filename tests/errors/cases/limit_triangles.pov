#version 3.7;
global_settings { assumed_gamma 1 }
#declare I = 0;
mesh {
#while (I < 100)
    triangle { <I, 0, 0>, <I + 1, 0, 0>, <I, 1, 0> }
    #declare I = I + 1;
#end
}
