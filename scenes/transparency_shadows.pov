// Golden scene: filter and transmit. Filtered panes tint what is behind them and cast coloured
// shadows; transmitted panes let light through untinted; rgbft mixes both. No ior change, so
// rays go straight through (transparency without refraction).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -8> look_at <0, 1, 0> angle 50 }
light_source { <2, 9, -7> color rgb 1 }
background { color rgb <0.25, 0.3, 0.35> }

plane { y, 0 pigment { color rgb 0.9 } }
plane { z, 3 pigment { checker color rgb 0.95 color rgb 0.6 } }

#declare Pane = box { <-0.6, 0, -0.05>, <0.6, 2, 0.05> }
object { Pane pigment { color rgbf <1, 0.2, 0.2, 0.9> } translate <-2.4, 0, 0> }
object { Pane pigment { color rgbf <0.2, 1, 0.3, 0.6> } translate <-0.8, 0, 0> }
object { Pane pigment { color rgbt <0.2, 0.4, 1, 0.7> } translate <0.8, 0, 0> }
object { Pane pigment { color rgbft <1, 0.9, 0.2, 0.5, 0.3> } translate <2.4, 0, 0> }

// Overlapping filtered spheres: the shadow where both overlap is the product of both tints.
sphere { <-0.5, 0.6, -1.8>, 0.6 pigment { color rgbf <1, 1, 0, 0.8> } finish { phong 0.6 } }
sphere { <0.5, 0.6, -2.2>, 0.6 pigment { color rgbf <0, 1, 1, 0.8> } finish { phong 0.6 } }
