// Golden scene: clipped_by (open cut: the inside of a clipped sphere shows), bounded_by as a
// pure accelerator (a bound that contains the object changes nothing), and the
// `clipped_by { bounded_by }` idiom that clips an object by its own bound. POV-Ray drops a bound
// it finds larger than the object's own box ("Unnecessary bounding object removed"); glint must
// draw the same either way.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.5, -7.5> look_at <0, 0.9, 0> angle 50 }
light_source { <-4, 9, -8> color rgb 1 }
light_source { <6, 4, -6> color rgb 0.3 shadowless }
background { color rgb <0.15, 0.2, 0.25> }

plane { y, 0 pigment { checker color rgb <0.8, 0.75, 0.7> color rgb <0.4, 0.4, 0.45> } }

// A sphere clipped by a plane: a bowl whose inside (same texture) shows.
sphere {
    <0, 0, 0>, 1
    clipped_by { plane { <0, 1, -1>, 0.1 } }
    pigment { color rgb <0.9, 0.35, 0.25> }
    finish { phong 0.5 }
    translate <-2.4, 1, 0>
}

// A torus inside a generous bounding box: identical to the torus without it. So is the union of
// little spheres in its box.
torus {
    0.8, 0.3
    bounded_by { box { <-1.2, -0.4, -1.2>, <1.2, 0.4, 1.2> } }
    pigment { color rgb <0.3, 0.7, 0.9> }
    finish { phong 0.5 }
    rotate -50 * x
    translate <0, 1.1, 0.5>
}

union {
    #declare I = 0;
    #while (I < 5)
        sphere { <0.45 * I - 0.9, 0, 0>, 0.22 }
        #declare I = I + 1;
    #end
    bounded_by { box { <-1.2, -0.25, -0.25>, <1.2, 0.25, 0.25> } }
    pigment { color rgb <0.85, 0.5, 0.95> }
    finish { phong 0.5 }
    translate <0, 2.6, 1.5>
}

// A cylinder clipped by its own bound (a sphere): rounded ends, open where the sphere cuts.
cylinder {
    <0, -1.2, 0>, <0, 1.2, 0>, 0.6
    bounded_by { sphere { <0, 0, 0>, 1.0 } }
    clipped_by { bounded_by }
    pigment { color rgb <0.95, 0.85, 0.3> }
    finish { phong 0.5 }
    rotate 30 * z
    translate <2.4, 1.1, 0>
}

// A box clipped by two spheres at once (both must contain the point).
box {
    <-0.6, -0.6, -0.6>, <0.6, 0.6, 0.6>
    clipped_by { sphere { <0, 0, 0>, 0.8 } sphere { <0.4, 0.4, -0.4>, 0.9 } }
    pigment { color rgb <0.45, 0.85, 0.4> }
    rotate 25 * y
    translate <0.3, 0.6, -2.2>
}
