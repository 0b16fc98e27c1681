// An animated scene for tests/farm: a sphere that moves with the clock.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -4> look_at 0 }
light_source { <3, 5, -4> color rgb 1 }
sphere { <clock * 2 - 1, 0, 0>, 0.6 pigment { rgb <1, 0.5, 0.2> } finish { phong 0.5 } }
plane { y, -0.6 pigment { checker rgb 0.2 rgb 0.8 } }
