// Golden scene: POV-Ray's sphere_sweep. Back: a linear_spline sweep (spheres joined by cones of
// varying radius). Middle: a cubic_spline sweep, turned. Front: a b_spline sweep with a box cut
// out of it (difference), whose inside test decides which of the box's faces show.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 8, -9> look_at <0, 0.5, 1.2> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 4, -6> color rgb 0.3 shadowless }
background { color rgb <0.2, 0.25, 0.3> }

plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.9> rgb <0.2, 0.3, 0.5> } }

sphere_sweep {
    linear_spline
    5,
    <-2.5, 0.5, 0>, 0.5
    <-1, 1.5, 0.5>, 0.3,
    <0.5, 0.8, -0.5>, 0.6,
    <1.8, 1.8, 0>, 0.2,
    <2.6, 0.6, 0.8>, 0.45
    pigment { rgb <0.9, 0.4, 0.2> }
    finish { phong 0.5 }
    translate <0, 0, 3>
}

sphere_sweep {
    cubic_spline
    6,
    <-3.5, 0.5, 0>, 0.2,
    <-2.2, 0.6, 0.4>, 0.35,
    <-0.8, 1.6, -0.3>, 0.5,
    <0.6, 0.6, 0.3>, 0.4,
    <2.0, 1.5, -0.2>, 0.3,
    <3.2, 0.4, 0.5>, 0.2
    pigment { rgb <0.3, 0.5, 0.9> }
    finish { phong 0.5 }
    rotate y * 10
    translate <0, 0, 1>
}

difference {
    sphere_sweep {
        b_spline
        6,
        <-3.5, 0.2, 0>, 0.3,
        <-2.2, 1.8, 0.2>, 0.5,
        <-0.8, 0.4, -0.4>, 0.7,
        <0.6, 1.6, 0.3>, 0.4,
        <2.0, 0.6, -0.2>, 0.6,
        <3.2, 2.0, 0.5>, 0.3
        tolerance 1e-6
    }
    box { <-0.6, 0.9, -2>, <0.6, 3, 2> }
    pigment { rgb <0.2, 0.8, 0.3> }
    finish { phong 0.5 }
    translate <0, 0, -1.5>
}
