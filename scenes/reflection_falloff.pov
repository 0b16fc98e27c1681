// Golden scene: reflection. Two facing mirrors make a corridor of images cut off by
// max_trace_level and adc_bailout; in front, three spheres: constant reflection, variable
// reflection { min max falloff } (weak face-on, strong at grazing angles), and metallic
// reflection tinted by the pigment.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 adc_bailout 0.02 }

camera { location <0.6, 2.2, -6> look_at <0, 1.1, 0> angle 60 }
light_source { <-3, 8, -6> color rgb 1 }
light_source { <4, 5, -3> color rgb 0.4 }
background { color rgb <0.4, 0.5, 0.7> }

plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.15 } finish { ambient 0.1 } }

// The mirrors, slightly tinted so that each bounce is visible.
#declare Mirror = texture { pigment { color rgb <0.85, 0.9, 1> }
                            finish { ambient 0 diffuse 0.05 reflection 0.85 } }
box { <-4, 0, 3>, <4, 3, 3.1> texture { Mirror } }
box { <-4, 0, -8.1>, <4, 3, -8> texture { Mirror } }

sphere { <-2, 0.8, 0>, 0.8 pigment { color rgb <0.9, 0.2, 0.2> }
         finish { ambient 0.05 diffuse 0.5 reflection 0.4 } }
sphere { <0, 0.8, 0>, 0.8 pigment { color rgb <0.2, 0.3, 0.9> }
         finish { ambient 0.05 diffuse 0.5 reflection { 0.05, 1.0 falloff 3 } } }
sphere { <2, 0.8, 0>, 0.8 pigment { color rgb <0.95, 0.7, 0.25> }
         finish { ambient 0.05 diffuse 0.2 specular 0.6 roughness 0.01
                  reflection { 0.8 metallic } } }
cylinder { <0, 0, 1.8>, <0, 2, 1.8>, 0.25 pigment { color rgb <0.3, 0.9, 0.4> } }
