// golden: close
// photons: POV-Ray's caustic photons. A glass ball focuses a spot light into a bright caustic
// inside its full shadow, a tinted clear slab passes coloured light as photons, and a mirror
// ring reflects a cardioid caustic onto the floor. Both renderers start each ring of photons
// at a random angle, so the images agree as VALIDATION.md's "close", not pixel for pixel.
#version 3.7;

global_settings {
  assumed_gamma 1.0
  photons { spacing 0.01 jitter 0 autostop 0 gather 20, 100 }
}

camera { location <0, 6, -7> look_at <0, 0.3, 0> angle 45 }

light_source { <-3, 9, 2> rgb 1.2 photons { refraction on reflection on } }
light_source { <4, 7, -6> rgb 0.3 shadowless }

plane { y, 0 pigment { rgb 0.8 } finish { ambient 0 diffuse 0.8 } }

sphere { <-1.4, 1, 0.4>, 0.9
  pigment { rgbf <0.95, 0.97, 1, 0.95> }
  finish { ambient 0 diffuse 0 reflection { 0.05, 1 fresnel on } specular 0.6 roughness 0.005 }
  interior { ior 1.5 }
  photons { target collect off }
}

box { <0.3, 1.2, -1.8>, <1.6, 1.3, -0.6>
  pigment { rgbf <0.3, 0.6, 1, 0.9> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.0 }
  photons { target collect off }
}

difference {
  cylinder { <1.6, 0, 1>, <1.6, 0.8, 1>, 1.1 }
  cylinder { <1.6, -0.1, 1>, <1.6, 0.9, 1>, 1.0 }
  pigment { rgb <1, 0.85, 0.5> }
  finish { ambient 0 diffuse 0.1 reflection 0.9 metallic }
  photons { target reflection on collect off }
}
