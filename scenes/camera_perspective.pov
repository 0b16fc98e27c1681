// Golden scene: a perspective camera spelled out in full: location, direction (its length sets
// the focal length), right and up (aspect and handedness), sky (the camera rolls 20 degrees),
// then look_at, and finally `angle`, which rescales the direction to give a 65 degree
// horizontal field of view (POV-Ray applies camera statements in order).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    perspective
    location <-3, 2.5, -6>
    direction <0, 0, 1.5>
    right x * 4 / 3
    up y
    sky <sin(radians(20)), cos(radians(20)), 0>
    look_at <0, 0.8, 0>
    angle 65
}
light_source { <-6, 9, -4> color rgb 1 }
background { color rgb <0.3, 0.4, 0.5> }

plane { y, 0 pigment { checker color rgb <0.9, 0.9, 0.85> color rgb <0.2, 0.3, 0.25> } }
box { <-0.5, 0, -0.5>, <0.5, 2.5, 0.5> pigment { color rgb <0.9, 0.4, 0.2> } translate <1.5, 0, 1> }
sphere { <-0.8, 0.7, 0.5>, 0.7 pigment { color rgb <0.2, 0.5, 0.9> } finish { phong 0.5 } }
cone { <0, 0, 0>, 0.5, <0, 1.6, 0>, 0 pigment { color rgb <0.3, 0.8, 0.3> }
       translate <0.3, 0, -1.6> }
