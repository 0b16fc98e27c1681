#version 3.7;
global_settings { assumed_gamma 1 }
object { obj_file { "no_such_model.obj" } }
