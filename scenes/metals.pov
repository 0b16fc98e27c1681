// Golden scene: POV-Ray's standard metals.inc (brass, copper, chrome, silver, gold; finishes A
// to E from dull to polished: ambient, brilliance, metallic specular, reflection) on spheres
// over a checker floor, under a gradient sky.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }

#include "colors.inc"
#include "metals.inc"

camera { location <0, 5.5, -9.5> look_at <0, 0.6, 0.6> angle 48 }
light_source { <-6, 12, -10> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 color rgb <0.9, 0.9, 0.85>]
                                             [1 color rgb <0.3, 0.45, 0.8>] } } }
plane { y, 0 pigment { checker color rgb 0.85 color rgb 0.25 } finish { ambient 0.1 } }

#macro Row(Z, TA, TB, TC, TD, TE)
    sphere { <-3.2, 0.55, Z>, 0.55 texture { TA } }
    sphere { <-1.6, 0.55, Z>, 0.55 texture { TB } }
    sphere { <0, 0.55, Z>, 0.55 texture { TC } }
    sphere { <1.6, 0.55, Z>, 0.55 texture { TD } }
    sphere { <3.2, 0.55, Z>, 0.55 texture { TE } }
#end
Row(-1.5, T_Gold_1A, T_Gold_2B, T_Gold_3C, T_Gold_4D, T_Gold_5E)
Row(0, T_Copper_1A, T_Silver_2B, T_Chrome_3C, T_Brass_4D, T_Copper_5E)
Row(1.5, T_Chrome_1A, T_Chrome_2B, T_Silver_3C, T_Silver_4D, T_Brass_5E)
