// VALIDATION.md case 7: a lit mesh2 pyramid on a floor. The test adds degenerate triangles
// (zero area, NaN, Inf and 1e30 vertices) and an empty mesh to the parsed scene: they must be
// skipped with a warning and the image must equal this one.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0.5, 2.5, -4> look_at <0, 0.5, 0> angle 55 }
light_source { <-3, 6, -4> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }

plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.3 } }
mesh2 {
    vertex_vectors { 5, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1>, <0, 1.5, 0> }
    face_indices { 4, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4> }
    pigment { color rgb <0.9, 0.5, 0.2> }
    finish { specular 0.5 reflection 0.1 }
}
