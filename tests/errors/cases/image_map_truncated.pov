#version 3.7;
global_settings { assumed_gamma 1 }
plane { y, 0
    pigment { image_map { png "image_map_truncated.png" } }
}
