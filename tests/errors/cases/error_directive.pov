#version 3.7;
global_settings { assumed_gamma 1 }
#declare Quality = 0;
#if (Quality < 1)
    #error "Quality must be at least 1"
#end
