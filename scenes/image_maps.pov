// Golden scene: image_map with map_type 0 (planar, repeated and `once`), 1 (spherical) and
// 2 (cylindrical), with and without `interpolate 2`; image maps under pigment transforms.
// glint_tex.png is made by make_texture.py.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.2, -7.5> look_at <0, 1.1, 0> angle 55 }
light_source { <-4, 8, -9> color rgb 1 }
light_source { <5, 4, -6> color rgb 0.3 shadowless }
background { color rgb <0.1, 0.1, 0.12> }

// Floor: the image repeated (planar map in x-y, turned onto the floor), small tiles.
plane { y, 0
        pigment { image_map { png "glint_tex.png" map_type 0 } scale <3, 1.5, 1> rotate 90 * x }
        finish { ambient 0.2 diffuse 0.6 } }

// Wall: a single copy (`once`), interpolated, over a colour-free background.
box { <-3.2, 0, 3>, <3.2, 4, 3.2>
      pigment { image_map { png "glint_tex.png" map_type 0 once interpolate 2 }
                scale <4, 2, 1> translate <-2, 1.6, 0> }
      finish { ambient 0.25 diffuse 0.6 } }

// Spherical map, not interpolated.
sphere { <0, 0, 0>, 1
         pigment { image_map { png "glint_tex.png" map_type 1 } }
         finish { phong 0.4 }
         rotate <0, 150, 0> translate <-2, 1, -0.5> }

// Cylindrical map (unit-height cylinder around y), interpolated.
cylinder { <0, 0, 0>, <0, 1, 0>, 0.8
           pigment { image_map { png "glint_tex.png" map_type 2 interpolate 2 } }
           finish { phong 0.4 }
           scale <1, 1.8, 1> rotate <0, 30, 0> translate <1.9, 0, -0.5> }
