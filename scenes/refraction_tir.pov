// Golden scene: refraction. Spheres of ior 1.0 (invisible but for its highlight), 1.33, 1.5 and
// 2.4 in front of a striped wall; a glass prism seen through a face at which total internal
// reflection happens; a block with interior fade (absorption grows with the path length).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }

camera { location <0, 2.5, -7> look_at <0, 1, 0> angle 55 }
light_source { <-4, 8, -6> color rgb 1 }
background { color rgb <0.2, 0.2, 0.25> }

plane { y, 0 pigment { checker color rgb <0.9, 0.85, 0.8> color rgb <0.3, 0.35, 0.4> } }
plane { z, 3 pigment { gradient x color_map { [0.0 color rgb <0.9, 0.2, 0.1>]
                                               [0.5 color rgb <0.9, 0.2, 0.1>]
                                               [0.5 color rgb <0.95, 0.95, 0.9>]
                                               [1.0 color rgb <0.95, 0.95, 0.9>] } scale 0.5 } }

#declare Glass = finish { ambient 0 diffuse 0 phong 0.8 phong_size 150 }
#macro Lens(X, Ior)
    sphere { <X, 1.6, 0>, 0.6 pigment { color rgbf <1, 1, 1, 1> } finish { Glass }
             interior { ior Ior } }
#end
Lens(-2.7, 1.0)
Lens(-0.9, 1.33)
Lens(0.9, 1.5)
Lens(2.7, 2.4)

// Right-angle prism (a box cut by a diagonal plane): light entering the front face meets the
// hypotenuse beyond the critical angle (41.8 degrees for ior 1.5) and is totally reflected.
intersection {
    box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6> }
    plane { <-1, 0, 1>, 0 }
    pigment { color rgbf <0.95, 1, 1, 0.95> }
    finish { Glass }
    interior { ior 1.5 }
    rotate -10 * y
    translate <-1.6, 0, -1.6>
}

// Block of tinted glass with interior fade.
box {
    <-0.8, 0, -0.4>, <0.8, 0.8, 0.4>
    pigment { color rgbf <1, 1, 1, 1> }
    finish { Glass }
    interior { ior 1.2 fade_distance 0.5 fade_power 1 fade_color <0.2, 0.5, 1> }
    rotate 25 * y
    translate <1.6, 0, -1.5>
}
