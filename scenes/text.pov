// text: TrueType glyphs extruded along z (timrom.ttf with kerning pairs AV, AW, Wo; cyrvetic.ttf
// with an offset vector between characters), a see-through glass text over a checker, a text in
// a CSG difference and glyphs seen edge-on, where the side walls (quadratic contours) show.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.6, -5> look_at <0, 0.7, 0> angle 60 }
light_source { <-6, 12, -10> rgb 1 }
light_source { <8, 4, -6> rgb 0.4 }
background { rgb <0.15, 0.2, 0.3> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 scale 0.5 } }

#declare Word = "AVWo glint";
text { ttf "timrom.ttf" Word 0.3, 0
    pigment { rgb <1, 0.55, 0.15> } finish { phong 0.6 }
    translate <-2.4, 1.3, 0>
}
text { ttf "cyrvetic.ttf" concat("Fog", str(42, 0, 0)) 0.5, <0.05, 0.02, 0>
    pigment { rgbf <0.6, 0.9, 1, 0.7> } finish { reflection 0.1 }
    interior { ior 1.3 }
    scale 0.8 rotate <0, -25, 0> translate <-2.2, 0.01, -0.6>
}
difference {
    box { <0, 0, 0> <1.6, 0.9, 0.3> }
    text { ttf "timrom.ttf" "Qg" 0.5, 0 translate <0.15, 0.3, -0.1> }
    pigment { rgb <0.3, 0.8, 0.4> }
    rotate <0, 35, 0> translate <0.8, 0.01, 0.2>
}
text { ttf "crystal.ttf" "edge" 1, 0 pigment { rgb <0.8, 0.3, 0.9> } scale 0.5 rotate <0, -70, 0> translate <1.2, 0.01, -2.6> }
