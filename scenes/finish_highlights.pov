// Golden scene: the classic finish model on a 5x4 grid of spheres, one parameter per row:
//   row 1: diffuse 0.3 .. 0.9 with brilliance 1 .. 8
//   row 2: phong 0.9 with phong_size 5 .. 200
//   row 3: specular 0.9 with roughness 0.2 .. 0.002
//   row 4: ambient 0 .. 0.6 (under global ambient_light), and metallic highlights
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <0.9, 0.95, 1.0> }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 10.8 up y * 8.1 }
light_source { <-8, 10, -12> color rgb 1 }
background { color rgb <0.12, 0.12, 0.14> }

#macro Ball(Column, Row, Finish)
    sphere { <-4 + 2 * Column, 3 - 2 * Row, 0>, 0.85
             pigment { color rgb <0.85, 0.45, 0.2> } finish { Finish } }
#end

#declare C = 0;
#while (C < 5)
    Ball(C, 0, finish { ambient 0.05 diffuse 0.3 + 0.15 * C brilliance 1 + 1.75 * C })
    Ball(C, 1, finish { ambient 0.05 diffuse 0.6 phong 0.9 phong_size pow(200 / 5, C / 4) * 5 })
    Ball(C, 2, finish { ambient 0.05 diffuse 0.6 specular 0.9 roughness 0.2 / pow(10, C / 2) })
    #if (C < 3)
        Ball(C, 3, finish { ambient 0.3 * C diffuse 0.5 })
    #else
        Ball(C, 3, finish { ambient 0.05 diffuse 0.5 phong 0.9 specular 0.6 roughness 0.02
                            metallic (C - 3) * 0.5 + 0.5 })
    #end
    #declare C = C + 1;
#end
