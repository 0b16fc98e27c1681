// Golden scene: CSG union, merge, intersection, difference, and inverse. The union and merge
// are the same two transparent spheres: the union shows the inner surfaces, the merge does not.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4.5, -8> look_at <0, 0.8, 0> angle 55 }
light_source { <-5, 10, -7> color rgb 1 }
background { color rgb <0.3, 0.3, 0.35> }

plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.55 } }

#declare Glassy = texture { pigment { color rgbt <0.5, 0.8, 1.0, 0.6> }
                            finish { ambient 0.1 diffuse 0.6 phong 0.6 } }
#declare Pair = sphere { <-0.45, 0, 0>, 0.75 } 

union { object { Pair } sphere { <0.45, 0, 0>, 0.75 } texture { Glassy } translate <-2.6, 0.9, 1> }
merge { object { Pair } sphere { <0.45, 0, 0>, 0.75 } texture { Glassy } translate <0.1, 0.9, 1> }

// Intersection: a lens from two spheres, in red.
intersection {
    sphere { <0, 0, -0.6>, 1 }
    sphere { <0, 0, 0.6>, 1 }
    pigment { color rgb <0.9, 0.25, 0.2> }
    finish { phong 0.5 }
    rotate <0, 65, 0>
    translate <2.7, 0.85, 1>
}

// Difference: a cube minus a sphere and a cylinder.
difference {
    box { <-0.8, -0.8, -0.8>, <0.8, 0.8, 0.8> }
    sphere { <0, 0, 0>, 1.05 }
    cylinder { <0, -1, 0>, <0, 1, 0>, 0.4 }
    pigment { color rgb <0.95, 0.75, 0.2> }
    finish { phong 0.4 }
    rotate <0, 30, 0>
    translate <-1.4, 0.8, -1.6>
}

// Inverse: the intersection of a box with an inverted sphere equals the difference.
intersection {
    box { <-0.7, -0.7, -0.7>, <0.7, 0.7, 0.7> }
    sphere { <0.7, 0.7, -0.7>, 0.8 inverse }
    pigment { color rgb <0.3, 0.8, 0.4> }
    finish { phong 0.4 }
    rotate <0, -20, 0>
    translate <1.5, 0.7, -1.6>
}
