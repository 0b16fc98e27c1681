global_settings { radiosity { count 2000000 } }
sphere { 0, 1 pigment { rgb 1 } }
