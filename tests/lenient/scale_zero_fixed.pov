// LENIENCY scale_zero_fixed: a zero scale component is replaced by 1 (Parse_Scale_Vector)
// POV-Ray 3.7: Warning "Illegal Value: Scale Y by 0.0. Changed to 1.0.". Effect: ordinary red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { 0, 1 scale <1,0,1> pigment { rgb <1,0,0> } }
