// LENIENCY texture_bare_ids: texture { PigmentId FinishId } without pigment{}/finish{} wrappers (Parse_Texture "pnf_ids" backwards-compatibility branch; Warn_State is silent for #version >= 1.5)
// POV-Ray 3.7: no warning. Effect: shiny red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare P = pigment { rgb <1,0,0> };
#declare F = finish { phong 1 };
sphere { 0, 1 texture { P F } }
