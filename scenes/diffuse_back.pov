// Golden scene: diffuse backside illumination (`diffuse A, B`, POV-Ray 3.7): thin leaves lit
// from behind by the first light show B of its diffuse light and no highlights on the side
// the camera sees; the second light, in front, lights them with A, highlights included. Flat
// polygons, so nothing of the leaf itself shadows its back.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -4> look_at <0, 0.5, 0> }
light_source { <-2, 4, 6> rgb 1 }
light_source { <3, 3, -4> rgb 0.3 }
#declare Leaf = polygon { 5, <-0.8, 0, 0>, <0.8, 0, 0>, <0.8, 1.2, 0>, <-0.8, 1.2, 0>, <-0.8, 0, 0> }
object { Leaf translate <-0.9, 0, 0> pigment { rgb <0.3, 0.8, 0.2> } finish { diffuse 0.6, 0.5 phong 0.5 } }
object { Leaf translate <0.9, 0, 0> rotate y*20 pigment { rgb <0.8, 0.6, 0.2> } finish { diffuse 0.3, 0.9 specular 0.4 } }
// A solid: its own far side shadows the backside light, as in POV-Ray.
sphere { <0, 0.3, -1>, 0.3 pigment { rgb 1 } finish { diffuse 0.7, 0.2 } }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.5 } }
