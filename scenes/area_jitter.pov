// area_light with jitter (a fine grid, so that glint's own random numbers and POV-Ray's give
// nearly the same soft shadow), adaptive, circular and orient; a light with looks_like (the
// glowing bulb is placed at the light and casts no shadow).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> }
light_source {
    <-3, 6, -2> rgb 0.8
    area_light <0.6, 0, 0>, <0, 0, 0.6>, 9, 9 adaptive 1 jitter circular orient
}
light_source {
    <1.8, 1.6, -0.8> rgb <0.5, 0.45, 0.4>
    looks_like { sphere { 0, 0.15 pigment { rgb <1, 1, 0.8> } finish { ambient 1 diffuse 0 } } }
}
background { rgb <0.2, 0.3, 0.5> }
sphere { <0, 0.8, 0> 0.8 pigment { rgb <0.9, 0.3, 0.2> } }
box { <-2.5, 0, 1.5> <-1.5, 1.2, 2> pigment { rgb <0.3, 0.6, 0.9> } }
plane { y, 0 pigment { rgb 0.8 } }
