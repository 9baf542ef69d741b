// LENIENCY comma_array_init: array initialiser without commas, trailing commas inside and after sub-lists, no ";" needed after an array #declare (Parse_Initalizer)
// POV-Ray 3.7: no warning. Effect: red sphere of radius A[1][0]=1
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare A = array[2][3] { {0.2 0.4 0.6,} {1 0 0,}, }
#declare B = array[2][2] { {1 2}{3 4} };
sphere { 0 A[1][0] pigment { rgb <1,0,0> } }
