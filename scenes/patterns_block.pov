// Golden scene: block and geometric patterns: brick (brick_size, mortar), hexagon, crackle
// (form, metric, offset, solid), radial with frequency, spiral1/spiral2, quilted (control0/1),
// cells, square, triangular, checker under a repeat warp, and a black_hole warp.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 8 * x up 6 * y }
light_source { <-20, 30, -40> color rgb 1 }
background { color rgb <0.2, 0.25, 0.3> }

#declare Tile = box { <-0.9, -0.9, 0>, <0.9, 0.9, 0.5> }
#declare Fin = finish { ambient 0.35 diffuse 0.65 }

// Top row.
object { Tile translate <-3, 2, 0>
         pigment { brick color rgb 0.8, color rgb <0.7, 0.25, 0.15> brick_size <0.5, 0.18, 0.3>
                   mortar 0.03 rotate -90 * x }
         finish { Fin } }
object { Tile translate <-1, 2, 0>
         pigment { hexagon color rgb <0.9, 0.2, 0.2>, color rgb <0.2, 0.8, 0.3>,
                   color rgb <0.2, 0.3, 0.9> scale 0.2 rotate -90 * x }
         finish { Fin } }
object { Tile translate <1, 2, 0>
         pigment { crackle color_map { [0 rgb 0] [0.05 rgb 0] [0.15 rgb <1, 0.9, 0.6>] [1 rgb 1] }
                   scale 0.3 }
         finish { Fin } }
object { Tile translate <3, 2, 0>
         pigment { crackle solid color_map { [0 rgb <0.2, 0.4, 0.1>] [1 rgb <0.9, 1, 0.5>] }
                   scale 0.25 }
         finish { Fin } }
// Middle row.
object { Tile translate <-3, 0, 0>
         pigment { radial frequency 6 color_map { [0 rgb <1, 0.9, 0.2>] [0.5 rgb <1, 0.9, 0.2>]
                                                   [0.5 rgb <0.1, 0.1, 0.5>] [1 rgb <0.1, 0.1, 0.5>] }
                   rotate -90 * x translate <-3, 0, 0> }
         finish { Fin } }
object { Tile translate <-1, 0, 0>
         pigment { spiral1 3 color_map { [0 rgb <0.1, 0.4, 0.8>] [1 rgb 1] } scale 0.3
                   translate <-1, 0, 0> }
         finish { Fin } }
object { Tile translate <1, 0, 0>
         pigment { spiral2 5 turbulence 0.1 color_map { [0 rgb <0.8, 0.2, 0.5>] [1 rgb 1] }
                   scale 0.5 translate <1, 0, 0> }
         finish { Fin } }
object { Tile translate <3, 0, 0>
         pigment { quilted control0 0.2 control1 0.9 color_map { [0 rgb <0.3, 0.1, 0.4>]
                                                                  [1 rgb <1, 0.8, 0.9>] }
                   scale 0.3 }
         finish { Fin } }
// Bottom row.
object { Tile translate <-3, -2, 0>
         pigment { cells color_map { [0 rgb <0.1, 0.3, 0.1>] [1 rgb <0.8, 1, 0.6>] } scale 0.2 }
         finish { Fin } }
object { Tile translate <-1, -2, 0>
         pigment { square color rgb 0.9, color rgb <0.9, 0.6, 0.1>, color rgb <0.1, 0.5, 0.6>,
                   color rgb 0.2 scale 0.2 rotate -90 * x }
         finish { Fin } }
object { Tile translate <1, -2, 0>
         pigment { triangular color rgb <1, 0, 0>, color rgb <1, 1, 0>, color rgb <0, 1, 0>,
                   color rgb <0, 1, 1>, color rgb <0, 0, 1>, color rgb <1, 0, 1>
                   scale 0.25 rotate -90 * x }
         finish { Fin } }
object { Tile translate <3, -2, 0>
         pigment { checker color rgb 1, color rgb <0.3, 0.3, 0.9>
                   warp { black_hole <15, -10, 0>, 3.5 strength 1.5 }
                   scale 0.2 }
         finish { Fin } }
