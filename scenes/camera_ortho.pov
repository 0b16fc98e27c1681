// Golden scene: orthographic camera looking down at an angle (parallel projection: equal
// boxes look equal at any distance), with explicit right/up giving the view size.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    orthographic
    location <6, 8, -6>
    look_at <0, 0, 0>
    right x * 8
    up y * 6
}
light_source { <-3, 10, -8> color rgb 1 }
background { color rgb <0.8, 0.85, 0.9> }

plane { y, 0 pigment { checker color rgb 0.85 color rgb 0.65 } }

#declare J = 0;
#while (J < 3)
    #declare I = 0;
    #while (I < 3)
        box { <-0.4, 0, -0.4>, <0.4, 0.8, 0.4>
              pigment { color rgb <0.3 + 0.3 * I, 0.4, 0.3 + 0.3 * J> } finish { phong 0.4 }
              translate <2 * I - 2, 0, 2 * J - 2> }
        #declare I = I + 1;
    #end
    #declare J = J + 1;
#end
sphere { <0, 1.6, 0>, 0.5 pigment { color rgb <1, 0.8, 0.2> } finish { phong 0.6 } }
