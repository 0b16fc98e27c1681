// subsurface: POV-Ray's subsurface light transport (finish subsurface with global_settings
// subsurface and mm_per_unit): a wax ball lit from the front, a thin marble slab lit from
// behind so that light comes through it, and a plain diffuse ball for comparison. Both
// renderers draw their samples at random (POV-Ray from its render-order stream), so the images
// agree as VALIDATION.md's "close", not pixel for pixel.
// golden: close
#version 3.7;
global_settings { assumed_gamma 1.0 mm_per_unit 40 subsurface { samples 60, 12 } }
camera { location <0, 2.2, -4.5> look_at <0, 0.7, 0> angle 48 }
light_source { <-30, 30, -30> rgb 1 }
light_source { <1.5, 2, 6> rgb <1, 0.9, 0.8> }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.45 scale 0.5 } }
sphere { <-1.2, 0.7, 0>, 0.7
  pigment { rgb <0.8, 0.5, 0.1> }
  finish { diffuse 0.6 specular 0.4 roughness 0.05 subsurface { translucency <5, 3, 1> * 0.5 } }
  interior { ior 1.45 } }
box { <-0.6, 0, -0.04>, <0.6, 1.6, 0.04>
  pigment { rgb <0.83, 0.79, 0.75> }
  finish { diffuse 0.8 subsurface { translucency <0.46, 0.38, 0.33> * 4 } }
  interior { ior 1.5 }
  rotate y * 20 translate <0.9, 0, 0.6> }
sphere { <0.2, 0.35, -1.2>, 0.35 pigment { rgb <0.8, 0.5, 0.1> } finish { diffuse 0.6 } }
