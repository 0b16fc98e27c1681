#version 3.7;
global_settings { assumed_gamma 1 }
// POV-Ray's Parse_Ovus: "Both Ovus radii must be positive".
ovus { 1, -0.5 pigment { rgb 1 } }
