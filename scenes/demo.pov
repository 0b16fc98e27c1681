// glint demo scene: reflection, refraction, shadows, a checker and an image texture.
// Renders with POV-Ray 3.7 and glint alike:
//   glint render scenes/demo.pov -o demo.png --width 640 --height 480 --aa adaptive
//   povray +Idemo.pov +Odemo.png +W640 +H480 +A0.3
// Uses glint_tex.png (made by make_texture.py beside this file).

#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }

#include "colors.inc"

camera {
    location <0.6, 2.6, -7.2>
    look_at <0.2, 0.9, 0>
    angle 52
}

light_source { <-6, 10, -8> color rgb <1.0, 0.97, 0.92> }
light_source { <7, 6, -3> color rgb 0.35 shadowless }

sky_sphere {
    pigment {
        gradient y
        color_map {
            [0.0 color rgb <0.85, 0.88, 0.95>]
            [0.5 color rgb <0.35, 0.55, 0.90>]
            [1.0 color rgb <0.10, 0.25, 0.70>]
        }
    }
}

// Checkered floor with a faint mirror finish.
plane {
    y, 0
    texture {
        pigment { checker color rgb <0.92, 0.90, 0.85> color rgb <0.12, 0.14, 0.18> scale 1.2 }
        finish { diffuse 0.8 ambient 0.08 reflection { 0.02, 0.25 falloff 2 } }
    }
}

// Glass sphere: refraction with a slight green absorption.
sphere {
    <-2.0, 1.0, 0.0>, 1.0
    texture {
        pigment { color rgbf <0.95, 1.0, 0.97, 0.92> }
        finish { ambient 0 diffuse 0.05 phong 0.9 phong_size 120 reflection { 0.04, 0.6 } }
    }
    interior { ior 1.5 fade_distance 2.5 fade_power 2 fade_color <0.6, 0.95, 0.75> }
}

// Chrome sphere: metallic reflection.
sphere {
    <1.75, 0.85, 0.5>, 0.85
    texture {
        pigment { color rgb <0.9, 0.92, 0.95> }
        finish {
            ambient 0 diffuse 0.1 specular 0.8 roughness 0.005 metallic
            reflection { 0.75 metallic }
        }
    }
}

// Picture block: the image texture on its front face, planar-mapped over the unit square.
box {
    <0, 0, 0>, <1, 1, 1>
    texture {
        pigment { image_map { png "glint_tex.png" map_type 0 interpolate 2 } }
        finish { ambient 0.15 diffuse 0.75 phong 0.3 }
    }
    translate <-0.5, 0, -0.5>
    scale <3.2, 1.6, 0.4>
    rotate -8 * y
    translate <-0.1, 0.01, 4.2>
}

// A row of small coloured tori, placed by a macro in a loop.
#macro Ring(Index, Color)
    torus {
        0.28, 0.08
        pigment { color Color }
        finish { phong 0.6 phong_size 60 }
        rotate 90 * x
        translate <0.45 + 0.62 * Index, 0.36, -1.6>
    }
#end
#declare I = 0;
#while (I < 4)
    #if (I < 2)
        Ring(I, rgb <1, 0.3 + 0.5 * I, 0.2>)
    #else
        Ring(I, rgb <0.3, 0.85 - 0.35 * (I - 2), 0.4 + 0.6 * (I - 2)>)
    #end
    #declare I = I + 1;
#end

// A striped cylinder with a cone on top (gradient colour map).
union {
    cylinder { <0, 0, 0>, <0, 1.2, 0>, 0.35 }
    cone { <0, 1.2, 0>, 0.45, <0, 1.9, 0>, 0 }
    texture {
        pigment {
            gradient y
            color_map { [0.0 color rgb <0.9, 0.2, 0.3>] [0.5 color rgb <0.95, 0.9, 0.8>]
                        [1.0 color rgb <0.9, 0.2, 0.3>] }
            scale 0.4
        }
        finish { phong 0.4 }
    }
    translate <3.4, 0, 2.6>
}
