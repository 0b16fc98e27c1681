#version 3.7;
global_settings { assumed_gamma 1 }
sphere { 0, 1 }
/* this comment never ends
sphere { 2, 1 }
