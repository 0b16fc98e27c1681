// Many lights (bench/README.md): N POV-Ray point and spot lights (default 100) of random
// colours over a floor with boxes, for the path tracer: the light tree against power alone
// (glint render bench/many_lights.pov --integrator path [--no-light-tree]).
#version 3.7;
#ifndef (N) #declare N = 100; #end
global_settings { assumed_gamma 1 }
camera { location <0, 9, -14> look_at <0, 0, 0> angle 60 }
plane { y, 0 pigment { rgb 0.7 } finish { diffuse 1 ambient 0 specular 0 } }
box { <-3, 0, -1>, <-1, 2.5, 1> pigment { rgb 0.7 } finish { diffuse 1 ambient 0 } }
box { <2, 0, 1>, <4, 1, 3> pigment { rgb 0.7 } finish { diffuse 1 ambient 0 } }
#declare R = seed(11);
#for (i, 0, N - 1)
  #declare P = <rand(R) * 20 - 10, 0.3 + rand(R) * 2, rand(R) * 20 - 10>;
  #if (mod(i, 2) = 0)
    light_source { P, rgb <rand(R), rand(R), rand(R)> * 20 / N fade_distance 1 fade_power 2 }
  #else
    light_source { P, rgb <rand(R), rand(R), rand(R)> * 20 / N spotlight point_at P - y
                   radius 25 falloff 40 fade_distance 1 fade_power 2 }
  #end
#end
