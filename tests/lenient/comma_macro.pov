// LENIENCY comma_macro: macro parameter list and macro call without commas, with trailing commas; any RValue (object, pigment, vector) may be passed (Parse_Macro, Invoke_Macro)
// POV-Ray 3.7: no warning. Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#macro Ball(C R P,)
  sphere { C, R pigment { P } }
#end
Ball(<0,0,0> 1 pigment { rgb <1,0,0> },)
