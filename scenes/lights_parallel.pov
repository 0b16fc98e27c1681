// Golden scene: a parallel light (sun-like: parallel shadows whatever the distance), a second
// parallel light that is a spotlight, and an object with no_shadow.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 7, -10> look_at <0, 0.5, 0> angle 45 }
background { color rgb <0.5, 0.6, 0.8> }

light_source { <-10, 12, -6> color rgb <1, 0.95, 0.85> parallel point_at <0, 0, 0> }
light_source { <6, 8, -4> color rgb <0.25, 0.3, 0.5> parallel point_at <0, 0, 0>
               spotlight radius 10 falloff 20 }

plane { y, 0 pigment { color rgb <0.8, 0.78, 0.7> } }

#declare I = 0;
#while (I < 5)
    cylinder { <0, 0, 0>, <0, 1.2 + 0.3 * I, 0>, 0.25
               pigment { color rgb <0.9, 0.4 + 0.1 * I, 0.3> } finish { phong 0.3 }
               translate <-3 + 1.5 * I, 0, 1.5> }
    #declare I = I + 1;
#end
sphere { <-1, 0.6, -1.5>, 0.6 pigment { color rgb <0.3, 0.6, 0.9> } }
sphere { <1.5, 0.6, -1.5>, 0.6 pigment { color rgb <0.9, 0.9, 0.3> } no_shadow }
