// LENIENCY flag_float_value: an object flag's value may be any float, as POV-Ray's Allow_Float reads it (`hollow 1`, `no_image 0`, `double_illuminate On`, `no_reflection (1 > 2)`): on when above zero; `hierarchy [on|off]` on a blob, mesh or height field (POV-Ray's bounding tree inside them: nothing to draw)
// POV-Ray 3.7: no warning. Effect: a white sphere, a smaller one at its right, a triangle mesh at the left and a blob below; the flags set to zero change nothing
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-5> look_at 0 }
light_source { <5,5,-5>, 1 }
background { rgb 0.2 }
#declare On = 1;
sphere { 0, 1 hollow 1 pigment { rgb 1 } no_image 0 double_illuminate On }
sphere { 1.4*x, 0.5 no_reflection (1 > 2) pigment { rgb <1,0.6,0.2> } no_shadow }
mesh { triangle { <-2.8,-1,0>, <-1.4,-1,0>, <-2.1,0.6,0> } hierarchy off pigment { rgb <0.3,0.6,1> } }
blob { threshold 0.5 sphere { <0,-1.6,0>, 0.6, 1 } hierarchy on pigment { rgb <0.5,1,0.5> } }
