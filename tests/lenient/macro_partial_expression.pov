// LENIENCY macro_partial_expression: a macro body may be an incomplete expression ("0.5 +"); the caller supplies the rest
// POV-Ray 3.7: no warning. Effect: red sphere of radius 0.5 + 0.5
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#macro PlusHalf() 0.5 + #end
sphere { 0, PlusHalf() 0.5 pigment { rgb <1,0,0> } }
