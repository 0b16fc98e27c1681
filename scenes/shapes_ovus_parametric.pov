// Golden scene: POV-Ray's ovus and parametric. Left: an egg (bottom radius above top radius);
// middle: an ovus whose top radius is the larger, uv-mapped checker (Ovus::UVCoord), turned;
// right: a squashed ovus lying on its side, reflective. Back: a Moebius strip as a parametric
// (fpmetric.cpp's subdivision, precompute, normals from the parametrisation), uv-mapped, turned
// and moved; its shadow falls on the floor and on itself.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.4, -5.5> look_at <0, 0.7, 0.8> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 3, -2> color rgb 0.4 }
background { color rgb <0.2, 0.25, 0.3> }

plane { y, -0.5 pigment { checker rgb <0.9, 0.9, 0.9> rgb <0.2, 0.3, 0.5> scale 0.5 } }

ovus { 1.0, 0.65
    pigment { color rgb <1, 0.9, 0.8> } finish { phong 0.5 }
    scale 0.7 translate <-1.6, 0, 0>
}
ovus { 0.6, 0.9
    pigment { uv_mapping checker rgb <1, 0.3, 0.2> rgb <1, 1, 0.6> scale <0.1, 0.1, 1> }
    rotate <20, 0, -25> translate <0.2, 0, 0.2>
}
ovus { 0.5, 0.2
    pigment { color rgb <0.4, 0.9, 0.5> } finish { phong 0.8 specular 0.3 reflection 0.2 }
    scale <1, 1.5, 1> rotate 90*x translate <1.8, 0.1, -0.6>
}

parametric {
    function { cos(u) + v * cos(u / 2) * cos(u) }
    function { sin(u) + v * cos(u / 2) * sin(u) }
    function { v * sin(u / 2) }
    <0, -0.3>, <2 * pi, 0.3>
    contained_by { box { <-1.4, -1.4, -0.35>, <1.4, 1.4, 0.35> } }
    accuracy 0.01
    max_gradient 1.5
    precompute 12, x, y, z
    pigment { uv_mapping checker rgb <0.3, 0.6, 1> rgb 1 scale <pi / 12, 0.15, 1> }
    finish { specular 0.4 }
    rotate <-60, 20, 0> translate <0.6, 1.4, 2.4>
}
