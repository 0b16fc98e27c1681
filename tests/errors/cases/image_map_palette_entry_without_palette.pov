#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -3> look_at 0 }
light_source { <2, 4, -3>, 1 }
// Mount1.png is a grey image: it has no palette whose entry 3 could be made transparent.
plane { z, 1
    pigment { image_map { png "Mount1.png" transmit 3, 0.5 } }
}
