#version 3.7;
global_settings { assumed_gamma 1 }
// Ten million strings: stopped by --max-memory (300 MiB here) long before they are all made.
#declare A = array[10000000]; #declare I = 0; #while (I < 10000000) #declare A[I] = concat("element ", str(I, 0, 0), " of a long list of strings"); #declare I = I + 1; #end
