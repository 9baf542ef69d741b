// LENIENCY include_ident: #include of a string identifier; #declare inside a vector
// POV-Ray 3.7: no warning (renders as trace does: tests/lenient/povray/include_ident.png)
#version 3.7;
#declare F = "lenient_hdr.inc";
#include F
#declare V = < 1, #declare Y = 2; Y, 0 >;
sphere { V, 0.5 pigment { rgb <1,0,1> } }
