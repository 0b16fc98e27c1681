// VALIDATION.md case 17: a perspective camera with field of view Fov degrees (#declare'd by
// the test) looking from <1, 2, -10> at a small marker sphere of radius Marker centred exactly
// on the look_at point, in front of a checker wall. The centre ray must hit the marker.
#ifndef (Fov) #declare Fov = 60; #end
#ifndef (Marker) #declare Marker = 0.01; #end
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare Target = <0.3, 1.1, 0.2>;
camera { location <1, 2, -10> look_at Target angle Fov }
light_source { <-5, 10, -10> color rgb 1 }
background { color rgb <0, 0, 0.3> }

plane { z, 20 pigment { checker color rgb 0.8 color rgb 0.4 } }
plane { y, -1 pigment { color rgb <0.5, 0.4, 0.3> } }
sphere { Target, Marker pigment { color rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } }
