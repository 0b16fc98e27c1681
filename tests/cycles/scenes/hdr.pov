// glint scene written by tests/cycles/make_scenes.py (Blender 3.4.1): do not edit.
// Blender (x, y, z) is POV (x, z, y) here; see make_scenes.py.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  perspective
  location <0.300000, 1.500000, -4.200000>
  sky <-0.014892, 0.977911, 0.208489>
  right x*128/96
  up y
  angle 50.692351
  look_at <0.230327, 1.290980, -3.224574>
}
background { color rgb 0 }
sky_sphere {
  pigment { image_map { exr "sky.exr" map_type 1 interpolate 2 } }
  scale <-1, 1, 1>
  emission 1
}
obj_file { "hdr.obj" }
