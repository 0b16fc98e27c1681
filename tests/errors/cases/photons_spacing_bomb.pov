// A spacing far too fine for the scene: shooting stops with an error, not out of memory.
global_settings { photons { spacing 0.00002 } }
camera { location <0, 2, -4> look_at 0 }
light_source { <0, 8, 0> rgb 1 photons { refraction on } }
plane { y, 0 pigment { rgb 1 } }
sphere { <0, 1, 0>, 1 pigment { rgbf 1 } interior { ior 1.5 } photons { target collect off } }
