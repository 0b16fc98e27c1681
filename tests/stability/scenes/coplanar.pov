// VALIDATION.md case 3: exactly coplanar, overlapping surfaces with different materials: two
// triangles, two faces of one mesh2 (each with its own texture), and two boxes whose top faces
// share the plane y = 0. Which one shows where they overlap must not depend on the thread
// count or the run (a deterministic tie-break), so the image is the same bit for bit.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0.3, 3, -4> look_at <0, 0, 0.5> angle 60 }
light_source { <-2, 6, -3> color rgb 1 }
background { color rgb <0.1, 0.1, 0.2> }

triangle { <-2.5, 0, -1>, <-0.5, 0, -1>, <-1.5, 0, 1> pigment { color rgb <1, 0, 0> } }
triangle { <-2.5, 0, 0.5>, <-0.5, 0, 0.5>, <-1.5, 0, -1.5> pigment { color rgb <0, 1, 0> } }

mesh2 {
    vertex_vectors { 6, <0, 0, -1>, <2, 0, -1>, <1, 0, 1>, <0, 0, 0.5>, <2, 0, 0.5>, <1, 0, -1.5> }
    texture_list { 2, texture { pigment { color rgb <0, 0, 1> } },
                      texture { pigment { color rgb <1, 1, 0> } } }
    face_indices { 2, <0, 1, 2>, 0, <3, 4, 5>, 1 }
}

box { <-1, -1, 1>, <0.5, 0, 2.5> pigment { color rgb <1, 0, 1> } }
box { <-0.5, -1, 1.5>, <1, 0, 3> pigment { color rgb <0, 1, 1> } }
