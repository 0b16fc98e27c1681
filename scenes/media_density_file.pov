// media_density_file: a df3 voxel grid (POV-Ray's own spiral.df3, from its include folder) as
// a media density, read with each interpolation: nearest voxel (0), trilinear (1) and
// tricubic (2), left to right; the grids tilted so their spiral shows.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -12> look_at 0 angle 40 }
background { rgb <0.02, 0.02, 0.05> }
light_source { <500, 500, -500> rgb 1 }
#macro Spiral(Interp, X)
  box { 0, 1
    pigment { rgbt 1 }
    interior {
      media {
        emission 1.2
        scattering { 1, 0.1 }
        intervals 1 samples 5 method 3
        density {
          density_file df3 "spiral.df3" interpolate Interp
          color_map { [0 rgb 0] [0.1 rgb <0.5, 0.5, 0.7>] [0.5 rgb <1, 0.5, 0.7>]
                      [0.7 rgb <1, 1, 0.7>] [1 rgb 1] }
        }
      }
    }
    hollow
    translate -0.5
    scale 3 * <1, 1, 0.15>
    rotate <55, 25, 0>
    translate X * x
  }
#end
Spiral(0, -3.4)
Spiral(1, 0)
Spiral(2, 3.4)
