global_settings { photons { gather 50, 20 } }
sphere { 0, 1 pigment { rgb 1 } }
