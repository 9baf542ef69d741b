// LENIENCY macro_redefine_shadow: a macro may be silently redefined (Parse_Macro removes the old MACRO_ID); parameter names may shadow existing identifiers of any type
// POV-Ray 3.7: no warning. Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#macro M() rgb <0,0,1> #end
#macro M() rgb <1,0,0> #end
#declare R = pigment { rgb 1 };
#macro Ball(R) sphere { 0, R pigment { M() } } #end
Ball(1)
