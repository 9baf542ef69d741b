// LENIENCY hash_double_and_space: "##declare" (a "#" before a directive "#") and "#   declare" (blanks/newline between "#" and the keyword) both work
// POV-Ray 3.7: no warning. Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
##declare R = 1;
#
  declare G = 0;
sphere { 0, R pigment { rgb <1,G,0> } }
