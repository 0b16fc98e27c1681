// Golden scene: sky_sphere with two layered pigments (a gradient sky and a partly transparent
// band of stripes over it), rotated; a mirror sphere reflects it. The background colour is
// hidden wherever the sky sphere is opaque.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 1.2, -5> look_at <0, 1.6, 0> angle 70 }
light_source { <3, 6, -5> color rgb 1 }
background { color rgb <1, 0, 1> }

sky_sphere {
    pigment {
        gradient y
        color_map {
            [0.00 color rgb <0.9, 0.6, 0.3>]
            [0.15 color rgb <0.95, 0.85, 0.7>]
            [0.50 color rgb <0.3, 0.5, 0.9>]
            [1.00 color rgb <0.05, 0.1, 0.4>]
        }
        scale 2
        translate -y
    }
    pigment {
        gradient x
        color_map {
            [0.0 color rgbt <1, 1, 1, 1>]
            [0.8 color rgbt <1, 1, 1, 1>]
            [0.9 color rgbt <1, 1, 1, 0.3>]
            [1.0 color rgbt <1, 1, 1, 1>]
        }
        scale 0.25
    }
    rotate -15 * z
}

plane { y, 0 pigment { color rgb <0.35, 0.3, 0.25> } }
sphere { <0, 1.2, 0>, 1.2 pigment { color rgb 0.1 } finish { ambient 0 diffuse 0.1
         reflection 0.9 phong 0.8 } }
