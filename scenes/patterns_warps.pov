// Golden scene: warps: repeat (offset, flip), black_hole (falloff, strength, inverse),
// cylindrical, spherical, toroidal, planar and cubic mappings, a turbulence warp with octaves,
// two warps in sequence, and classic turbulence after a warp.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 8 * x up 6 * y }
light_source { <-20, 30, -40> color rgb 1 }
background { color rgb <0.2, 0.25, 0.3> }

#declare Tile = box { <-0.9, -0.9, 0>, <0.9, 0.9, 0.5> }
#declare Fin = finish { ambient 0.35 diffuse 0.65 }
#declare Map = color_map { [0 rgb <0.1, 0.2, 0.5>] [0.5 rgb <1, 0.9, 0.6>] [1 rgb <0.6, 0.1, 0.1>] }

// Top row.
object { Tile translate <-3, 2, 0>
         pigment { gradient x color_map { Map } warp { repeat x * 0.5 offset <0, 0.3, 0> flip x }
                   scale 0.5 } finish { Fin } }
object { Tile translate <-1, 2, 0>
         pigment { checker color rgb 1, color rgb <0.2, 0.5, 0.3>
                   warp { black_hole <-5, 10, 0>, 4 falloff 1.5 strength 1.2 inverse }
                   scale 0.2 } finish { Fin } }
object { Tile translate <1, 2, 0>
         pigment { checker color rgb 1, color rgb <0.6, 0.3, 0.1>
                   warp { cylindrical orientation y dist_exp 0.5 } scale 0.1
                   translate <1, 2, -1> } finish { Fin } }
object { Tile translate <3, 2, 0>
         pigment { bozo color_map { Map } warp { spherical orientation z dist_exp 1 }
                   scale 0.2 translate <3, 2, -0.5> } finish { Fin } }
// Middle row.
object { Tile translate <-3, 0, 0>
         pigment { checker color rgb 1, color rgb <0.1, 0.4, 0.7>
                   warp { toroidal orientation y major_radius 0.6 dist_exp 0.2 } scale 0.15
                   translate <-3, 0, -0.3> } finish { Fin } }
object { Tile translate <-1, 0, 0>
         pigment { granite color_map { Map } warp { planar z, 0.3 } scale 3 } finish { Fin } }
object { Tile translate <1, 0, 0>
         pigment { bozo color_map { Map } warp { cubic } scale 0.3
                   translate <1.05, 0.07, -0.41> } finish { Fin } }
object { Tile translate <3, 0, 0>
         pigment { gradient y color_map { Map } warp { turbulence 0.6 octaves 3 lambda 2.5 }
                   scale 0.4 } finish { Fin } }
// Bottom row.
object { Tile translate <-3, -2, 0>
         pigment { bozo color_map { Map }
                   warp { repeat y * 0.6 offset <0.4, 0, 0> }
                   warp { turbulence 0.3 } scale 0.3 } finish { Fin } }
object { Tile translate <-1, -2, 0>
         pigment { wood color_map { Map } warp { repeat x * 0.4 flip y } turbulence 0.1
                   scale 0.2 } finish { Fin } }
object { Tile translate <1, -2, 0>
         pigment { marble color_map { Map } turbulence 0.5 warp { black_hole <0, 0, 0>, 5 }
                   scale 0.3 translate <1, -2, 0> } finish { Fin } }
object { Tile translate <3, -2, 0>
         pigment { agate color_map { Map } turbulence 0.2 octaves 4 omega 0.4 scale 0.5 }
         finish { Fin } }
