global_settings { radiosity { pretrace_start 0.01 pretrace_end 0.2 } }
sphere { 0, 1 pigment { rgb 1 } }
