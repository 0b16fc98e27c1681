// fog: a constant fog with filter (tinting what lies behind it), a ground fog (fog_type 2)
// along a tilted up vector with transmit as its least transmittance, and a turbulent fog
// (turbulence, octaves, omega, lambda, turb_depth); the three combine. A hollow glass sphere
// lets the fog in; inside the solid one the refracted rays see none.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -6> look_at <0, 0.8, 0> }
light_source { <-5, 10, -10> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
fog { distance 25 color rgbf <0.3, 0.35, 0.5, 0.4> }
fog { fog_type 2 distance 4 color rgbt <0.5, 0.35, 0.3, 0.15> fog_offset 0.25 fog_alt 0.35
      up <0.1, 1, 0> rotate <0, 0, 5> }
fog { distance 40 color rgb <0.2, 0.25, 0.3> turbulence <0.6, 0.3, 0.5> octaves 4 omega 0.6
      lambda 2.2 turb_depth 0.4 }
sphere { <-1.3, 1, 1> 0.9 pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.2 } hollow }
sphere { <1.3, 1, 1> 0.9 pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.2 } }
sphere { <2, 0.5, 7> 0.5 pigment { rgb <0.2, 1, 0.2> } }
plane { y, 0 pigment { checker rgb 1 rgb 0.3 } }
