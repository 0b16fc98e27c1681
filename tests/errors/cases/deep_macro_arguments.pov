#version 3.7;
global_settings { assumed_gamma 1 }
// A macro call whose argument never closes, inside a #while whose #end sits in that argument:
// each pass calls the macro again from inside the previous call's argument (found by fuzz_pov).
#macro Ball(F) sphere { 0, 1 finish { F } } #end
#declare C = 0;
#while (C < 5) Ball(finish { ambient 0.05 #end
