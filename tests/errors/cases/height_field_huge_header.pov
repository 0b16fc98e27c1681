#version 3.7;
global_settings { assumed_gamma 1 }
height_field { png "image_map_huge_header.png" }
