// LENIENCY number_forms: float literal forms: "1." ".5" "1e0" "1E+0" and a dangling exponent "1e" (Read_Float stops, sscanf reads 1)
// POV-Ray 3.7: no warning. Effect: red sphere of radius 1e = 1
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare A = 1.;
#declare B = .5;
#declare C = 1e0;
#declare D = 1E+0;
#declare F = 2.5e-1;
#debug concat(str(A,0,3)," ",str(B,0,3)," ",str(C,0,3)," ",str(D,0,3)," ",str(F,0,3),"\n")
sphere { 0, 1e pigment { rgb <1,0,0> } }
