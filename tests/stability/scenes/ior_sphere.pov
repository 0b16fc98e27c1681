// VALIDATION.md case 15: a clear sphere of index Ior (#declare'd by the test) over a checker
// floor, and a clear cube turned so that rays meet its inner faces beyond the critical angle
// (total internal reflection). With Ior = 1 and Show_Cube = 0 the sphere must vanish: the
// image equals the one without it (Show_Sphere = 0).
#ifndef (Ior) #declare Ior = 1.0; #end
#ifndef (Show_Sphere) #declare Show_Sphere = 1; #end
#ifndef (Show_Cube) #declare Show_Cube = 0; #end
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }

camera { location <0, 2.5, -6> look_at <0, 0.8, 0> angle 50 }
light_source { <-3, 7, -5> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }

plane { y, 0 pigment { checker color rgb 0.9 color rgb <0.2, 0.3, 0.2> } }
#if (Show_Sphere)
    sphere { <-0.8, 1, 0>, 1
             pigment { color rgbf <1, 1, 1, 1> }
             finish { ambient 0 diffuse 0 }
             interior { ior Ior } }
#end
#if (Show_Cube)
    box { <-0.6, -0.6, -0.6>, <0.6, 0.6, 0.6>
          pigment { color rgbf <1, 1, 1, 1> }
          finish { ambient 0 diffuse 0 }
          interior { ior Ior }
          rotate <35, 45, 0> translate <1.5, 1, 0> }
#end
