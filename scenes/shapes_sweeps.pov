// Golden scene: POV-Ray's swept and revolved shapes. Back row: prisms (linear_spline with a
// hole, quadratic_spline, cubic_spline conic_sweep, bezier_spline open). Front row: lathes
// (linear, quadratic, cubic, bezier) and sors (closed, open), one prism cut by a difference.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 7, -11> look_at <0, 0.2, 1.2> angle 50 }
light_source { <-6, 10, -7> color rgb 1 }
light_source { <6, 5, -3> color rgb 0.3 shadowless }
background { color rgb <0.2, 0.25, 0.3> }

#declare Matte = finish { ambient 0.12 diffuse 0.75 phong 0.3 phong_size 25 }

plane { y, 0 pigment { color rgb <0.75, 0.72, 0.65> } finish { Matte } }

// A square with a square hole: two closed sub-outlines.
prism { linear_sweep linear_spline 0, 1.2, 10,
        <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>,
        <-0.5, -0.5>, <0.5, -0.5>, <0.5, 0.5>, <-0.5, 0.5>, <-0.5, -0.5>
        pigment { color rgb <0.9, 0.3, 0.2> } finish { Matte } rotate 20 * y translate <-4.2, 0, 3> }
prism { quadratic_spline 0, 1, 6,
        <0, -1>, <1, 0>, <0, 1.2>, <-1, 0>, <0, -1>, <1, 0>
        pigment { color rgb <0.95, 0.75, 0.2> } finish { Matte } translate <-1.5, 0, 3> }
prism { conic_sweep cubic_spline 0.4, 1, 7,
        <-1, 1>, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>, <1, -1>
        pigment { color rgb <0.3, 0.8, 0.35> } finish { Matte }
        rotate 180 * x translate <1.3, 1.05, 3> }
prism { bezier_spline 0, 0.8, 8,
        <0, -1>, <1.4, -1>, <1.4, 1>, <0, 1>,  <0, 1>, <-1.4, 1>, <-1.4, -1>, <0, -1>
        open
        pigment { color rgb <0.3, 0.5, 0.95> } finish { Matte } rotate -30 * y translate <4.1, 0, 3> }

lathe { linear_spline 5, <0, 0>, <0.8, 0>, <0.5, 0.7>, <0.6, 1.4>, <0, 1.6>
        pigment { color rgb <0.85, 0.45, 0.9> } finish { Matte } translate <-4.5, 0, 0> }
lathe { quadratic_spline 5, <0, 0>, <0.7, 0>, <0.3, 0.7>, <0.7, 1.4>, <0.2, 1.8>
        pigment { color rgb <0.2, 0.85, 0.8> } finish { Matte } translate <-2.6, 0, 0> }
lathe { cubic_spline 7, <0, 0>, <0.7, 0>, <0.4, 0.5>, <0.7, 1>, <0.3, 1.5>, <0.5, 1.9>, <0, 2.2>
        pigment { color rgb <0.95, 0.55, 0.2> } finish { Matte } translate <-0.8, 0, 0> }
lathe { bezier_spline 8, <0.1, 0>, <0.9, 0>, <0.9, 0.8>, <0.4, 1>,  <0.4, 1>, <0, 1.2>, <0.8, 1.6>, <0.1, 1.8>
        pigment { color rgb <0.9, 0.9, 0.3> } finish { Matte } translate <1, 0, 0> }
sor { 7, <0, -0.5>, <0.7, 0>, <0.4, 0.5>, <0.75, 1>, <0.35, 1.5>, <0.6, 1.9>, <0.5, 2.2>
      pigment { color rgb <0.6, 0.6, 0.95> } finish { Matte } translate <2.8, 0, 0> }
sor { 6, <0.5, -0.3>, <0.6, 0>, <0.3, 0.6>, <0.7, 1.2>, <0.8, 1.6>, <0.6, 2>
      open
      pigment { color rgb <0.95, 0.4, 0.5> } finish { Matte } rotate -25 * x translate <4.6, 0.4, -0.6> }

difference {
    prism { linear_spline -0.5, 0.5, 4, <0, 1>, <0.9, -0.6>, <-0.9, -0.6>, <0, 1> }
    sphere { <0, 0.5, 0>, 0.6 }
    pigment { color rgb <0.95, 0.95, 0.95> } finish { Matte }
    rotate <0, 30, 0> translate <0, 0.5, -2.6>
}
