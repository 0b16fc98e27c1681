// Golden scene: the analytic shapes (sphere, plane, box, cylinder closed and open, cone closed
// and open, disc with a hole, torus) and every transform (translate, rotate, scale, matrix).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -9> look_at <0, 0.6, 0> angle 55 }
light_source { <-5, 9, -6> color rgb 1 }
background { color rgb <0.2, 0.25, 0.3> }

#declare Matte = finish { ambient 0.12 diffuse 0.75 phong 0.4 phong_size 30 }

plane { y, 0 pigment { color rgb <0.75, 0.72, 0.65> } finish { Matte } }

// Back row.
sphere { <0, 0, 0>, 1 pigment { color rgb <0.9, 0.25, 0.2> } finish { Matte }
         scale <1, 0.6, 0.8> translate <-3, 0.6, 2> }
box { <-0.7, 0, -0.7>, <0.7, 1.4, 0.7> pigment { color rgb <0.25, 0.6, 0.9> } finish { Matte }
      rotate 30 * y translate <0, 0, 2> }
cylinder { <0, 0, 0>, <0, 1.6, 0>, 0.6 pigment { color rgb <0.3, 0.8, 0.35> } finish { Matte }
           translate <3, 0, 2> }

// Front row: open cylinder and open cone (their insides show), a closed cone, a torus.
cylinder { <0, 0, 0>, <0, 1, 0>, 0.55 open pigment { color rgb <0.95, 0.8, 0.2> }
           finish { Matte } rotate -35 * x translate <-3.2, 0.6, -1> }
cone { <0, 0, 0>, 0.7, <0, 1.3, 0>, 0.2 pigment { color rgb <0.85, 0.45, 0.9> } finish { Matte }
       translate <-1.1, 0, -1.2> }
cone { <0, 0, 0>, 0.25, <0, 1, 0>, 0.6 open pigment { color rgb <0.95, 0.55, 0.2> }
       finish { Matte } rotate 25 * z translate <0.9, 0.15, -1.4> }
torus { 0.6, 0.2 pigment { color rgb <0.2, 0.85, 0.8> } finish { Matte }
        rotate <60, 0, 20> translate <3, 0.8, -1> }

// Disc with a hole, standing up; sheared box through a matrix.
disc { <0, 0, 0>, <0, 0, 1>, 0.9, 0.4 pigment { color rgb <1, 1, 1> } finish { Matte }
       rotate -20 * y translate <-1.5, 1.2, 4.5> }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> pigment { color rgb <0.9, 0.6, 0.5> } finish { Matte }
      matrix < 1, 0, 0,
               0.5, 1, 0,
               0, 0, 1,
               1.5, 0, 4.5 > }
