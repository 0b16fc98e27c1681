// golden: close
// radiosity: POV-Ray's irradiance cache in a diffuse box: red and green walls bleed colour onto
// a white floor and a white sphere, a spot light lights the ceiling indirectly, an emissive
// panel adds light of its own, and a no_radiosity box stays out of the gathered light. Both
// renderers place cache samples from jittered pretrace pixels, so the images agree as
// VALIDATION.md's "close", not pixel for pixel.
#version 3.7;

global_settings {
  assumed_gamma 1.0
  radiosity {
    pretrace_start 0.08
    pretrace_end 0.02
    count 120
    nearest_count 8
    error_bound 0.6
    recursion_limit 2
    low_error_factor 0.5
    brightness 1
  }
}

camera { location <0, 2.5, -6.5> look_at <0, 2.2, 0> angle 55 }

light_source { <0, 4.6, -1> rgb 1.2 spotlight point_at <0, 0, 0> radius 25 falloff 40 }

#declare Matte = finish { ambient 0 diffuse 0.8 }
#declare White = texture { pigment { rgb 0.9 } finish { Matte } }

box { <-3, 0, -7>, <3, 5, 3> inverse texture { White } }                  // the room
box { <-3.01, 0, -7>, <-2.99, 5, 3> pigment { rgb <0.8, 0.1, 0.1> } finish { Matte } }
box { <2.99, 0, -7>, <3.01, 5, 3> pigment { rgb <0.1, 0.7, 0.15> } finish { Matte } }
sphere { <-1.1, 1, 0.5>, 1 texture { White } }
box { <0.4, 0, -0.6>, <2, 2.2, 1> rotate 20*y pigment { rgb <0.3, 0.4, 0.9> } finish { Matte } }
box { <-0.8, 4.98, 1.5>, <0.8, 5, 2.5> pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 3 } }
box { <-2.9, 3.4, 0.5>, <-2.3, 4.0, 1.1> pigment { rgb <1, 0.9, 0.2> } finish { Matte } no_radiosity }
