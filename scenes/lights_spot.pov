// Golden scene: spot lights (radius, falloff, tightness; coloured), a point light with
// fade_distance/fade_power, a shadowless fill light, and shadows from each.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.6 }

camera { location <0, 6, -9> look_at <0, 0.5, 0> angle 50 }
background { color rgb 0 }

// Hard-edged red spot (radius = falloff) and a soft, tight blue one.
light_source { <-3, 6, -2> color rgb <1, 0.3, 0.25>
               spotlight point_at <-2, 0, 1> radius 14 falloff 14 }
light_source { <3, 7, -3> color rgb <0.35, 0.5, 1.2>
               spotlight point_at <2, 0, 1> radius 8 falloff 22 tightness 10 }
// A faded green point light close to the floor at the back.
light_source { <0, 1.2, 3.5> color rgb <0.3, 1.2, 0.3> fade_distance 1.5 fade_power 2 }
// A dim white fill with no shadows.
light_source { <0, 10, -10> color rgb 0.15 shadowless }

plane { y, 0 pigment { color rgb 0.85 } finish { ambient 0.05 diffuse 0.9 } }
plane { z, 5 pigment { color rgb 0.7 } finish { ambient 0.05 diffuse 0.9 } }

sphere { <-2, 0.7, 1>, 0.7 pigment { color rgb 0.9 } finish { phong 0.6 } }
cylinder { <2, 0, 1>, <2, 1.6, 1>, 0.4 pigment { color rgb 0.9 } finish { phong 0.6 } }
box { <-0.5, 0, 2.5>, <0.5, 1, 3> pigment { color rgb 0.9 } }
