// caustic: a glass ball on a floor, lit by one small bright ball; its caustic is light that
// reaches the floor only through the glass (light -> glass -> glass -> floor -> camera).
// A path tracer finds that light only when a path bounced off the floor happens to pass
// through the ball and hit the small light; photons carry it from the light. With
// PointLight=1 (glint's --declare PointLight=1) the light is a point: no path can hit it,
// and only the photon integrator (--integrator sppm) renders the caustic.
#version 3.7;

global_settings { assumed_gamma 1.0 }

#ifndef (PointLight) #declare PointLight = 0; #end

camera { location <0, 3.4, -5.2> look_at <0, 0.55, 0.2> angle 38 }

#if (PointLight)
  // fade_power 2: the light dims with the square of distance, as a physical point light.
  light_source { <-1.6, 4.2, 1.2> rgb 1600 fade_distance 0.05 fade_power 2 }
#else
  sphere { <-1.6, 4.2, 1.2>, 0.12
    pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 90 }
  }
#end

plane { y, 0 pigment { rgb 0.8 } finish { ambient 0 diffuse 1 } }
plane { -z, -2.5 pigment { rgb <0.8, 0.75, 0.7> } finish { ambient 0 diffuse 1 } }

sphere { <0, 0.8, 0.2>, 0.8
  pigment { rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5 }
}
