// Golden scene: the noise-based patterns with POV-Ray 3.7's noise (noise_generator 2):
// bozo, granite, agate, marble, wood, spotted, leopard and onion, most with turbulence
// (amount, octaves, omega, lambda), colour maps, frequency/phase and wave types.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 8 * x up 6 * y }
light_source { <-20, 30, -40> color rgb 1 }
background { color rgb <0.2, 0.25, 0.3> }

#declare Tile = box { <-0.9, -1.35, 0>, <0.9, 1.35, 0.5> }
#declare Fin = finish { ambient 0.35 diffuse 0.65 }

// Top row.
object { Tile translate <-3, 1.5, 0>
         pigment { bozo turbulence 0.4 color_map { [0 rgb <0.1, 0.2, 0.6>] [0.5 rgb <0.9, 0.9, 1>]
                                                    [1 rgb <0.2, 0.5, 0.2>] } scale 0.5 }
         finish { Fin } }
object { Tile translate <-1, 1.5, 0>
         pigment { granite color_map { [0 rgb 0.15] [0.4 rgb <0.8, 0.6, 0.5>] [1 rgb 1] }
                   scale 2 }
         finish { Fin } }
object { Tile translate <1, 1.5, 0>
         pigment { agate agate_turb 0.6 color_map { [0 rgb <0.5, 0.2, 0.1>] [0.6 rgb <1, 0.8, 0.5>]
                                                    [1 rgb <0.3, 0.1, 0>] } scale 0.8 }
         finish { Fin } }
object { Tile translate <3, 1.5, 0>
         pigment { marble turbulence 0.9 octaves 5 omega 0.6 lambda 2.2
                   color_map { [0 rgb 0.95] [0.7 rgb <0.7, 0.7, 0.8>] [1 rgb <0.2, 0.2, 0.3>] }
                   rotate 30 * z scale 0.7 }
         finish { Fin } }
// Bottom row.
object { Tile translate <-3, -1.5, 0>
         pigment { wood turbulence <0.08, 0.06, 0.1> color_map { [0 rgb <0.9, 0.6, 0.3>]
                                                                  [1 rgb <0.5, 0.25, 0.1>] }
                   rotate <70, 10, 0> scale 0.25 }
         finish { Fin } }
object { Tile translate <-1, -1.5, 0>
         pigment { spotted frequency 2 phase 0.3 sine_wave
                   color_map { [0 rgb <0.9, 0.1, 0.1>] [1 rgb <1, 1, 0.4>] } scale 0.4 }
         finish { Fin } }
object { Tile translate <1, -1.5, 0>
         pigment { leopard color_map { [0 rgb 1] [0.3 rgb <0.9, 0.7, 0.2>] [0.6 rgb 0.1] }
                   scale 0.08 }
         finish { Fin } }
object { Tile translate <3, -1.5, 0>
         pigment { onion turbulence 0.3 lambda 3 triangle_wave
                   color_map { [0 rgb <0.2, 0.6, 0.9>] [1 rgb <0.9, 0.95, 1>] } scale 0.6 }
         finish { Fin } }
