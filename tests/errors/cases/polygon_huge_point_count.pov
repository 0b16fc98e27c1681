#version 3.7;
global_settings { assumed_gamma 1 }
// A count past int's range is checked before it becomes an int (found by fuzz_pov under UBSan).
polygon { 1e19, <0, 0>, <1, 0>, <0, 1> pigment { rgb 1 } }
