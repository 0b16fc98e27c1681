// Golden scene: height_field from an 8-bit grey PNG (scenes/heightfield.png, written by
// make_heightfield.py): POV-Ray's two triangles per cell, water_level cutting the low border
// away, smooth normals on the right copy, and a height field inside a CSG intersection.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 7, -9> look_at <0, 0.4, 0.5> angle 50 }
light_source { <-6, 10, -7> color rgb 1 }
light_source { <6, 5, -3> color rgb 0.3 shadowless }
background { color rgb <0.2, 0.25, 0.3> }

#declare Matte = finish { ambient 0.12 diffuse 0.75 phong 0.2 phong_size 20 }

plane { y, 0 pigment { color rgb <0.35, 0.45, 0.6> } finish { Matte } }

height_field { png "heightfield.png" water_level 0.12
               pigment { gradient y color_map { [0 color rgb <0.3, 0.6, 0.25>]
                                                [0.5 color rgb <0.7, 0.6, 0.4>]
                                                [1 color rgb <0.95, 0.95, 0.95>] } }
               finish { Matte } translate <-1.05, 0, -0.5> scale <3.8, 1.6, 3.8> }
height_field { png "heightfield.png" smooth
               pigment { color rgb <0.85, 0.55, 0.3> } finish { Matte }
               translate <0.05, 0, -0.5> scale <3.8, 1.6, 3.8> }
intersection {
    height_field { "heightfield.png" translate <-0.5, 0, -0.5> scale <3, 1.2, 3> }
    sphere { <0, 0, 0>, 1.3 }
    pigment { color rgb <0.9, 0.85, 0.3> } finish { Matte } translate <0, 0.01, -2.8>
}
