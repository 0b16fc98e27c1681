#version 3.7;
global_settings { assumed_gamma 1 }
mesh2 {
    vertex_vectors { 2, <0,0,0>, <1,0,0>, <0,1,0> }
    face_indices { 1, <0, 1, 2> }
}
