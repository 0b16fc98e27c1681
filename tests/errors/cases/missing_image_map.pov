#version 3.7;
global_settings { assumed_gamma 1 }
plane { y, 0
    pigment { image_map { png "no_such_image.png" } }
}
