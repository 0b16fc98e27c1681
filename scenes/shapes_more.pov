// Golden scene: quadric (ellipsoid, and a clipped hyperboloid), polygon (with a hole),
// superellipsoids (rounded box, star-like), blobs (spheres, a cylinder, a negative component,
// a scaled component) and a cubic poly, with CSG of a quadric and a blob.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 6, -10> look_at <0, 0.3, 1> angle 55 }
light_source { <-6, 10, -7> color rgb 1 }
light_source { <6, 5, -3> color rgb 0.3 shadowless }
background { color rgb <0.2, 0.25, 0.3> }

#declare Matte = finish { ambient 0.12 diffuse 0.75 phong 0.3 phong_size 25 }

plane { y, 0 pigment { color rgb <0.75, 0.72, 0.65> } finish { Matte } }

// Ellipsoid x^2 + 2 y^2 + z^2 + xy = 0.8.
quadric { <1, 2, 1>, <1, 0, 0>, <0, 0, 0>, -0.8
          pigment { color rgb <0.9, 0.3, 0.2> } finish { Matte } translate <-4, 0.8, 2.5> }
// Hyperboloid of one sheet x^2 - y^2 + z^2 = 0.2, clipped to a box.
quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.2
          clipped_by { box { <-1, -0.9, -1>, <1, 0.9, 1> } }
          pigment { color rgb <0.95, 0.75, 0.2> } finish { Matte } translate <-1.5, 0.9, 2.5> }
polygon { 10, <-1, 0>, <1, 0>, <1, 1.6>, <-1, 1.6>, <-1, 0>,
              <-0.4, 0.5>, <0.4, 0.5>, <0.4, 1.1>, <-0.4, 1.1>, <-0.4, 0.5>
          pigment { color rgb <0.3, 0.8, 0.35> } finish { Matte } rotate -20 * y translate <1, 0, 2.8> }
superellipsoid { <0.25, 0.25> pigment { color rgb <0.3, 0.5, 0.95> } finish { Matte }
                 scale 0.7 rotate <0, 30, 0> translate <3.8, 0.7, 2.5> }
superellipsoid { <2.5, 0.6> pigment { color rgb <0.85, 0.45, 0.9> } finish { Matte }
                 scale 0.8 rotate <20, 30, 0> translate <-4, 0.9, -0.8> }

blob { threshold 0.6
       sphere { <-0.6, 0, 0>, 0.9, 1 }
       sphere { <0.6, 0, 0>, 0.9, 1 }
       sphere { <0, 0.7, 0>, 0.8, strength 1 scale <1, 1.4, 1> }
       cylinder { <-0.9, -0.4, -0.5>, <0.9, -0.4, 0.5>, 0.45, 1 }
       sphere { <0, 0.2, -0.7>, 0.6, -1.5 }
       pigment { color rgb <0.2, 0.85, 0.8> } finish { Matte } translate <-1.2, 0.9, -0.6> }

intersection {
    blob { threshold 0.5 sphere { <0, 0, -0.5>, 1.2, 1 } sphere { <0, 0, 0.5>, 1.2, 1 } }
    quadric { <0, 1, 1>, <0, 0, 0>, <0, 0, 0>, -0.5 }
    pigment { color rgb <0.95, 0.55, 0.2> } finish { Matte } rotate 50 * y translate <1.6, 0.75, -0.8>
}

// Cubic: x^3 - 0.3 x + y^2 + z^2 - 0.3 = 0 (inside where negative), clipped.
cubic { <1, 0, 0, 0, 0, 0, 0, 0, 0, -0.3, 0, 0, 1, 0, 0, 0, 1, 0, 0, -0.3>
        clipped_by { box { <-1.2, -1.2, -1.2>, <1.2, 1.2, 1.2> } }
        pigment { color rgb <0.9, 0.9, 0.3> } finish { Matte } rotate 90 * z translate <4.2, 0.9, -0.8> }
