// pigment_map, texture_map (blended and block entries), layered textures, average and warps:
// glint's surface shading per texture and per layer against POV-Ray 3.7.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -6.5> look_at <0, 0.7, 0> angle 50 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 4, -6> color rgb 0.4 shadowless }

#declare Stripes = pigment_map {
    [0.3 color rgb <0.9, 0.85, 0.7>]
    [0.3 bozo color_map { [0 rgb <0.2, 0.3, 0.8>] [1 rgb <0.9, 0.2, 0.1>] } scale 0.15]
}
#declare Glaze = texture { pigment { rgbt <0.2, 0.8, 0.3, 0.6> } finish { phong 0.8 } }

plane { y, 0
    texture { checker
        texture { pigment { rgb 0.85 } }
        texture { pigment { marble turbulence 0.6 color_map { [0 rgb 0.3] [1 rgb 0.6] } }
                  finish { reflection 0.15 } }
        scale 1.5 }
}
// pigment_map with a warp
sphere { <-2.2, 1, 0>, 1
    pigment { gradient y pigment_map { Stripes } warp { turbulence 0.3 } scale 0.5 }
    finish { specular 0.4 }
}
// texture_map: blended entries with their own normals and finishes
sphere { <0, 1, 0.5>, 1
    texture { wood turbulence 0.2 scale 0.4 rotate x * 70
        texture_map {
            [0.3 pigment { rgb <0.6, 0.3, 0.1> } normal { bumps 0.5 scale 0.05 } ]
            [0.7 pigment { rgb <0.95, 0.8, 0.5> } finish { phong 0.6 reflection 0.1 } ]
        }
    }
}
// layered textures: a see-through layer with its own normal over a spotted base
sphere { <2.2, 1, 0>, 1
    texture { pigment { spotted color_map { [0 rgb <0.8, 0.1, 0.1>] [1 rgb <0.1, 0.1, 0.8>] }
                        scale 0.3 } }
    texture { pigment { hexagon color rgbt <1, 1, 1, 1> color rgbt <1, 1, 0.2, 0.3>
                        color rgbt <0, 0, 0, 1> scale 0.2 rotate x * 90 } }
    texture { Glaze normal { ripples 0.4 scale 0.3 } }
}
// average of pigments, on a box
box { <-0.6, 0, -2.4>, <0.6, 0.5, -1.6>
    pigment { average pigment_map { [1 checker rgb x, rgb y scale 0.2] [2 agate] [1 rgb z] } }
}
