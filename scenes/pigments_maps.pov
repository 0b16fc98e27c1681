// Golden scene: pigments. Plain colours written as color / rgb / rgbf / rgbt / srgb; checker of
// two colours and of two nested pigments; gradient with a colour map (sharp and smooth
// entries); pigment transforms and texture transforms; uv_mapping on a sphere and a box.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#include "colors.inc"

camera { location <0, 8.5, -7.5> look_at <0, 0.2, 0.3> angle 52 }
light_source { <-5, 10, -8> color rgb 1 }
background { color srgb <0.35, 0.4, 0.5> }

plane { y, 0
        texture { pigment { checker pigment { color White }
                                    pigment { color rgb <0.2, 0.25, 0.35> } }
                  scale 1.5 rotate 30 * y translate <0.3, 0, 0> } }

// Back row: the colour spellings.
sphere { <-3, 0.6, 2.5>, 0.6 pigment { color Orange } }
sphere { <-1.5, 0.6, 2.5>, 0.6 pigment { rgb <0.2, 0.7, 0.3> } }
sphere { <0, 0.6, 2.5>, 0.6 pigment { rgbf <0.9, 0.2, 0.9, 0.5> } }
sphere { <1.5, 0.6, 2.5>, 0.6 pigment { rgbt <0.2, 0.5, 0.9, 0.5> } }
sphere { <3, 0.6, 2.5>, 0.6 pigment { srgb <0.8, 0.55, 0.1> } }

// Middle row: gradient colour maps, scaled, rotated and translated.
box { <-1, 0, -0.3>, <1, 1.2, 0.3>
      pigment { gradient x color_map { [0.0 color Red] [0.33 color Yellow] [0.66 color Blue]
                                       [1.0 color Red] } scale 2 translate -x }
      translate <-2.4, 0, 0.5> }
box { <-1, 0, -0.3>, <1, 1.2, 0.3>
      pigment { gradient y color_map { [0.0 color rgb <0.1, 0.1, 0.5>]
                                       [0.5 color rgb <0.1, 0.1, 0.5>]
                                       [0.5 color rgb <1, 0.9, 0.3>] [1.0 color rgb <1, 0.5, 0.1>] }
                scale 0.4 rotate 35 * z }
      translate <0, 0, 0.5> }
cylinder { <0, 0, 0>, <0, 1.4, 0>, 0.5
           texture { pigment { gradient <1, 1, 0> color_map { [0 color Green] [1 color White] }
                               scale 0.3 } }
           translate <2.4, 0, 0.5> }

// Front row: a texture transformed as a whole; uv-mapped checkers on a sphere and a box.
sphere { <0, 0, 0>, 0.6
         texture { pigment { checker color rgb <0.9, 0.3, 0.1> color rgb <1, 0.95, 0.8> }
                   scale 0.25 rotate <30, 20, 0> }
         translate <-2.2, 0.6, -1.8> }
sphere { <0, 0, 0>, 0.6
         pigment { uv_mapping checker color rgb <0.1, 0.5, 0.9> color rgb <1, 1, 1>
                   scale <1 / 12, 1 / 6, 1> }
         rotate <-20, 30, 0> translate <0, 0.6, -1.8> }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5>
      pigment { uv_mapping checker color rgb <0.2, 0.7, 0.3> color rgb <1, 1, 0.9>
                scale 0.125 }
      rotate 35 * y translate <2.2, 0, -1.8> }
