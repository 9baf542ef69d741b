// LENIENCY unary_plus_chain: unary plus is skipped any number of times (Parse_Num_Factor CASE(PLUS_TOKEN) has no EXIT): "+ + +1"; "- -1" is 1
// POV-Ray 3.7: no warning. Effect: red sphere of radius 1
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { 0, + + +1 pigment { rgb <1,0,0> } }
sphere { 0, - -1 pigment { rgb <1,0,0> } }
