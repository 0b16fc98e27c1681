#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -3> look_at 0 }
light_source { <2, 4, -3>, 1 }
// test.png's palette has 16 entries: 0 to 15.
plane { z, 1
    pigment { image_map { png "test.png" filter 2, 0.5 filter 16, 0.5 } }
}
