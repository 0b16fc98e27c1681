#version 3.7;
global_settings { assumed_gamma 1 }
// A position past int's range is the same error as one just past the end (found by fuzz_expr).
#declare T = substr("abc", 3e11, 2e9);
