// VALIDATION.md case 2: an endless lit ground plane seen at grazing angles from Distance units
// away (#declare'd by the test; default 1e5), under a parallel light, with a faint mirror
// finish. Every point of the plane has the same normal, light direction and reflected sky, so
// every pixel showing it must have the same colour: any pixel that differs is acne (a shadow
// or reflection ray that hit the plane it started on).
#ifndef (Distance) #declare Distance = 1e5; #end
#ifndef (Height) #declare Height = 50; #end
#ifndef (Reflection) #declare Reflection = 0.2; #end
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, Height, -Distance> look_at <0, 0, 0> angle 40 }
// Far enough that every visible plane point lies beyond the light plane, so shadow rays are
// traced there (POV-Ray skips shadow tests for points behind a parallel light's plane).
light_source { <-1, 2, -1> * 1e7 color rgb 1 parallel point_at <0, 0, 0> }
background { color rgb <0.3, 0.4, 0.6> }

plane { y, 0 pigment { color rgb <0.7, 0.7, 0.65> }
        finish { ambient 0.1 diffuse 0.6 reflection Reflection } }
