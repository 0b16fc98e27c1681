// Normal perturbation against POV-Ray 3.7: the special normals (bumps, dents, ripples, waves,
// wrinkles, quilted), the slope of a pattern with accuracy and a slope_map, a normal_map, block
// pattern normals, average, bump_size, and reflection of the perturbed normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5.5, -9> look_at <0, 0.6, 0.5> angle 52 }
light_source { <-8, 12, -10> color rgb 1 }
light_source { <8, 6, -4> color rgb 0.35 }

#declare F = finish { phong 0.7 phong_size 30 }
#declare P = pigment { rgb <0.9, 0.8, 0.6> }

plane { y, 0 pigment { rgb 0.7 }
    normal { brick normal { granite 0.6 scale 0.3 } normal { waves 0.4 scale 0.2 }
             brick_size <1.2, 0.6, 0.6> mortar 0.08 }
    finish { reflection 0.1 }
}
sphere { <-3, 0.8, 2>, 0.8 pigment { P } finish { F } normal { bumps 0.6 scale 0.15 } }
sphere { <-1, 0.8, 2>, 0.8 pigment { P } finish { F } normal { dents bump_size 1.2 scale 0.2 } }
sphere { <1, 0.8, 2>, 0.8 pigment { P } finish { F } normal { ripples 0.8 frequency 2 scale 0.5 } }
sphere { <3, 0.8, 2>, 0.8 pigment { P } finish { F } normal { wrinkles 0.7 scale 0.3 } }
sphere { <-3, 0.8, 0>, 0.8 pigment { P } finish { F }
    normal { gradient y 0.8 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } scale 0.3 } }
sphere { <-1, 0.8, 0>, 0.8 pigment { P } finish { F }
    normal { leopard 1.5 accuracy 0.01 turbulence 0.2 scale 0.15 } }
sphere { <1, 0.8, 0>, 0.8 pigment { P } finish { F }
    normal { gradient x normal_map { [0.3 bumps 0.5 scale 0.1] [0.7 quilted 0.8 scale 0.25] }
             scale 0.8 } }
sphere { <3, 0.8, 0>, 0.8 pigment { P } finish { F reflection 0.3 }
    normal { average normal_map { [1 waves 0.5 scale 0.3] [1 crackle 0.6 scale 0.3] } } }
box { <-1.5, 0, -2.2>, <1.5, 0.4, -1.4> pigment { rgb <0.5, 0.6, 0.9> } finish { F }
    normal { checker normal { onion 0.8 scale 0.1 } normal { spiral1 3 0.5 scale 0.2 }
             scale 0.4 } }
