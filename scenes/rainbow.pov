// rainbow: two bows with color maps using filter and transmit, a distance that lets nearby
// objects show through, an up vector, arc_angle with falloff_angle fading the ends (and one bow
// with arc_angle alone).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -6> look_at <0, 1.5, 0> }
light_source { <-5, 10, -10> rgb 1 }
background { rgb <0.25, 0.35, 0.55> }
rainbow {
    angle 22 width 8 distance 20 direction <-0.2, 0.1, 1> up <0.1, 1, 0>
    arc_angle 140 falloff_angle 100
    color_map {
        [0.0 rgbt <1, 0, 0, 0.3>] [0.3 rgbft <1, 1, 0, 0.2, 0.2>]
        [0.6 rgbt <0, 1, 0, 0.5>] [1.0 rgbt <0, 0, 1, 0.8>]
    }
}
rainbow {
    angle 12 width 3 direction <0.1, 0, 1> arc_angle 200
    color_map { [0.0 rgbt <1, 0, 1, 0.5>] [1.0 rgbt <0, 1, 1, 0.5>] }
}
sphere { <0, 1, 2> 1 pigment { rgb <1, 0.2, 0.2> } }
plane { y, 0 pigment { checker rgb 1 rgb 0.3 } }
