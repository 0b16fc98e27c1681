// Many emitters (bench/README.md): N small emitting spheres over a floor, the same total power
// for every N (declare N in the file, default 10,000). The light tree against power alone:
// glint render bench/many_emitters.pov --integrator path [--no-light-tree].
#version 3.7;
#ifndef (N) #declare N = 10000; #end
global_settings { assumed_gamma 1 }
camera { location <0, 9, -14> look_at <0, 0, 0> angle 60 }
plane { y, 0 pigment { rgb 0.7 } finish { diffuse 1 ambient 0 specular 0 } }
box { <-3, 0, -1>, <-1, 2.5, 1> pigment { rgb 0.7 } finish { diffuse 1 ambient 0 } }
box { <2, 0, 1>, <4, 1, 3> pigment { rgb 0.7 } finish { diffuse 1 ambient 0 } }
#declare R = seed(7);
#for (i, 0, N - 1)
  #declare C = <rand(R), rand(R), rand(R)>;
  sphere { <rand(R) * 20 - 10, 0.2 + rand(R) * 3, rand(R) * 20 - 10>, 0.04
    pigment { rgb C } finish { emission 4000 / N ambient 0 diffuse 0 specular 0 } }
#end
