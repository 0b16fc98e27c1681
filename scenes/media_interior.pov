// media_interior: POV-Ray media inside hollow objects. Left: absorbing and emitting media
// with a spherical density and a density_map; middle: scattering (Henyey-Greenstein) lit by a
// spotlight, with the sphere's own shadow in it and an object shadowing part of it; right: two
// media of different scattering types in one box, one with two densities that multiply. The
// floor shows the shadows the media cast (their extinction along the shadow rays).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -7> look_at <0, 0.9, 0> angle 50 }
light_source { <-6, 9, -6> rgb 0.9 }
light_source { <2, 6, -2> rgb <1, 0.9, 0.7> spotlight point_at <0, 0.8, 0> radius 12 falloff 20
               tightness 5 }
background { rgb <0.15, 0.2, 0.3> }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.4 scale 0.5 } }

sphere { 0, 1
  pigment { rgbt 1 } hollow
  interior {
    media {
      absorption <0.9, 0.5, 0.2>
      emission <0.6, 0.3, 0.1>
      density { spherical
        density_map { [0 rgb 0] [0.4 rgb 0.5] [1 rgb <1.6, 1.2, 1>] }
      }
    }
  }
  translate <-2.2, 1, 0.3>
}

sphere { <0, 1, 0> 1
  pigment { rgbt 1 } hollow
  interior {
    media {
      scattering { 5, rgb <1.2, 1.4, 1.8> eccentricity 0.45 }
      absorption 0.2
      intervals 3
      samples 4, 4
    }
  }
}
box { <-0.3, 2.6, -0.3> <0.3, 2.7, 0.3> pigment { rgb <0.9, 0.2, 0.2> } }

box { <-0.8, 0, -0.8> <0.8, 1.6, 0.8>
  pigment { rgbt 1 } hollow
  interior {
    media {
      scattering { 2, rgb 0.35 extinction 0.6 }
      density { gradient y color_map { [0 rgb 1] [1 rgb 0.1] } }
      density { bozo scale 0.3 color_map { [0 rgb 0.2] [1 rgb <1.4, 1, 0.7>] } }
    }
    media { emission <0, 0.12, 0.2> scattering { 4, rgb <0.1, 0.2, 0.5> } }
  }
  rotate y * 30
  translate <2.3, 0, 0.4>
}
