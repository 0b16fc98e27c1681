#version 3.7;
global_settings { assumed_gamma 1 }
// lemon came with POV-Ray 3.8: POV-Ray 3.7 stops at it ("undeclared identifier 'lemon'").
camera { location <0, 1, -4> look_at 0 }
light_source { <5, 5, -5> rgb 1 }
lemon { <0, -1, 0>, 0.5, <0, 1, 0>, 0.3, 1.5 pigment { rgb 1 } }
