#version 3.7;
global_settings { assumed_gamma 1 }
#declare Zero = 0;
sphere { 0, 1 / Zero }
