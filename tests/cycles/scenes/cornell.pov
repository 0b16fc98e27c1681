// glint scene written by tests/cycles/make_scenes.py (Blender 3.4.1): do not edit.
// Blender (x, y, z) is POV (x, z, y) here; see make_scenes.py.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  perspective
  location <0.000000, 1.000000, -3.900000>
  sky <0.000000, 1.000000, 0.000000>
  right x*128/96
  up y
  angle 54.432227
  look_at <0.000000, 1.000000, -2.900000>
}
background { color rgb <0.000000, 0.000000, 0.000000> }
obj_file { "cornell.obj" }
