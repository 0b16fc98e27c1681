// media_methods: the sampling methods on one emitting, absorbing medium with a crackle density:
// method 2 (stratified, intervals and samples), method 3 with a deep aa_level and a small
// aa_threshold, and method 3 with several intervals and an odd sample count. Each ball sits in
// front of a striped wall seen through it, and shadows it. (Method 1 and method 2's extra
// samples by confidence/variance draw random numbers, which POV-Ray takes from its render-order
// stream: they cannot agree pixel for pixel, and unit tests cover them.)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at <0, 0, 0> angle 45 }
light_source { <-4, 6, -8> rgb 1 }
plane { -z, -2 pigment { gradient x color_map { [0.5 rgb 0.9] [0.5 rgb 0.2] } scale 0.4 } }
#declare M = media {
  emission <0.5, 0.8, 1>
  absorption <1.2, 0.6, 0.3>
  density { crackle scale 0.4 color_map { [0 rgb 0] [0.3 rgb 0.4] [1 rgb 1.5] } }
}
sphere { <-1.6, 0, 0> 0.75 pigment { rgbt 1 } hollow
  interior { media { M method 2 intervals 4 samples 6, 6 } } }
sphere { <0, 0, 0> 0.75 pigment { rgbt 1 } hollow
  interior { media { M method 3 samples 4 aa_level 5 aa_threshold 0.02 } } }
sphere { <1.6, 0, 0> 0.75 pigment { rgbt 1 } hollow
  interior { media { M method 3 intervals 3 samples 7 } } }
