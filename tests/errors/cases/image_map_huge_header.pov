#version 3.7;
global_settings { assumed_gamma 1 }
// 70 bytes of PNG whose header says 100000 x 100000: refused before 160 GB are allocated.
plane { y, 0
    pigment { image_map { png "image_map_huge_header.png" } }
}
