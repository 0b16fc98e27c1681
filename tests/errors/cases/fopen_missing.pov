#version 3.7;
global_settings { assumed_gamma 1 }
#fopen F "no_such_file.txt" read
