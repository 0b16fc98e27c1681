// Golden scene: triangle, smooth_triangle and mesh (flat and smooth-shaded faces). The wavy
// patch is a mesh of smooth triangles with analytic normals, built by #while loops; the
// pyramid is a flat mesh; two single triangles and a smooth_triangle stand in front.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4.2, -7> look_at <0, 0.5, 0.5> angle 50 }
light_source { <-4, 8, -5> color rgb 1 }
light_source { <5, 3, -4> color rgb 0.3 }
background { color rgb <0.05, 0.07, 0.12> }

plane { y, -0.5 pigment { color rgb <0.5, 0.5, 0.55> } }

#declare Shiny = finish { ambient 0.1 diffuse 0.7 phong 0.8 phong_size 40 }

// Height y = A sin(K x) cos(K z): normals from the partial derivatives.
#declare A = 0.35;
#declare K = 2.0;
#macro P(X, Z) <X, A * sin(K * X) * cos(K * Z), Z> #end
#macro N(X, Z) <-A * K * cos(K * X) * cos(K * Z), 1, A * K * sin(K * X) * sin(K * Z)> #end
#declare Steps = 14;
#declare Size = 3.0;
mesh {
    #declare J = 0;
    #while (J < Steps)
        #declare I = 0;
        #while (I < Steps)
            #declare X0 = -Size / 2 + Size * I / Steps;
            #declare X1 = -Size / 2 + Size * (I + 1) / Steps;
            #declare Z0 = -Size / 2 + Size * J / Steps;
            #declare Z1 = -Size / 2 + Size * (J + 1) / Steps;
            smooth_triangle { P(X0, Z0), N(X0, Z0), P(X1, Z0), N(X1, Z0), P(X1, Z1), N(X1, Z1) }
            smooth_triangle { P(X0, Z0), N(X0, Z0), P(X1, Z1), N(X1, Z1), P(X0, Z1), N(X0, Z1) }
            #declare I = I + 1;
        #end
        #declare J = J + 1;
    #end
    pigment { color rgb <0.3, 0.55, 0.95> }
    finish { Shiny }
    translate <-1.2, 0.3, 1.2>
}

// Flat-shaded pyramid mesh.
mesh {
    triangle { <-1, 0, -1>, <1, 0, -1>, <0, 1.5, 0> }
    triangle { <1, 0, -1>, <1, 0, 1>, <0, 1.5, 0> }
    triangle { <1, 0, 1>, <-1, 0, 1>, <0, 1.5, 0> }
    triangle { <-1, 0, 1>, <-1, 0, -1>, <0, 1.5, 0> }
    pigment { color rgb <0.95, 0.7, 0.25> }
    finish { Shiny }
    rotate 20 * y
    translate <2.2, -0.5, 1.5>
}

// A lone triangle and a lone smooth_triangle (normals fanned out, so it looks curved).
triangle { <-3, -0.5, -1.5>, <-1.6, -0.5, -1.8>, <-2.4, 1.2, -1.2>
           pigment { color rgb <0.9, 0.3, 0.3> } finish { Shiny } }
smooth_triangle {
    <0.5, -0.4, -2>, <-0.6, 0.3, -1>,
    <2.5, -0.4, -2>, <0.6, 0.3, -1>,
    <1.5, 1.3, -1.6>, <0, 1, -0.6>
    pigment { color rgb <0.4, 0.9, 0.45> } finish { Shiny }
}
