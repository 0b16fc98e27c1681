#version 3.7;
global_settings { assumed_gamma 1 }
// mesh2 face indices past int's range are checked like any out-of-range index (found by fuzz_pov under UBSan).
mesh2 { vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } face_indices { 1, <0, 1, 2e72> } }
