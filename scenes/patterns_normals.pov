// Golden scene: normal perturbation by the patterns POV-Ray perturbs directly (bumps, dents,
// wrinkles, ripples, waves, quilted, facets) and through the pattern's slope (granite, crackle),
// with bump sizes, scales, frequency/phase and turbulence. Phong highlights make the normals
// visible.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 8 * x up 6 * y }
light_source { <-20, 30, -40> color rgb 1 }
background { color rgb <0.2, 0.25, 0.3> }

#declare Tile = box { <-0.9, -0.9, 0>, <0.9, 0.9, 0.5> }
#declare Tex = texture { pigment { rgb <0.85, 0.8, 0.7> }
                         finish { ambient 0.25 diffuse 0.75 phong 0.6 phong_size 30 } }

// Top row.
object { Tile translate <-3, 2, 0> texture { Tex normal { bumps 0.8 scale 0.15 } } }
object { Tile translate <-1, 2, 0> texture { Tex normal { dents 1.5 scale 0.3 } } }
object { Tile translate <1, 2, 0> texture { Tex normal { wrinkles 0.9 scale 0.4 } } }
object { Tile translate <3, 2, 0>
         texture { Tex normal { bumps 0.6 turbulence 0.5 scale 0.2 } } }
// Middle row.
object { Tile translate <-3, 0, 0>
         texture { Tex normal { ripples 0.8 frequency 3 phase 0.25 scale 0.5 } } }
object { Tile translate <-1, 0, 0> texture { Tex normal { waves 0.7 frequency 2 scale 0.4 } } }
object { Tile translate <1, 0, 0>
         texture { Tex normal { quilted 0.9 control0 0.3 control1 0.8 scale 0.3 } } }
object { Tile translate <3, 0, 0> texture { Tex normal { facets coords 0.4 size 0.2 } } }
// Bottom row.
object { Tile translate <-3, -2, 0> texture { Tex normal { granite 0.4 scale 1.5 } } }
object { Tile translate <-1, -2, 0> texture { Tex normal { crackle 0.8 scale 0.3 } } }
object { Tile translate <1, -2, 0>
         texture { Tex normal { wrinkles 0.5 scale <0.6, 0.2, 0.6> rotate 30 * z } } }
object { Tile translate <3, -2, 0> texture { Tex normal { dents 0.8 noise_generator 1 scale 0.2 } } }
