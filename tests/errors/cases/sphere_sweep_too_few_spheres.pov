#version 3.7;
global_settings { assumed_gamma 1 }
// A b_spline sweep builds each piece from four consecutive spheres: three are too few.
sphere_sweep { b_spline 3, <0, 0, 0>, 1, <1, 0, 0>, 1, <2, 0, 0>, 1 pigment { rgb 1 } }
