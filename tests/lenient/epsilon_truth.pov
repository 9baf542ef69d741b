// LENIENCY epsilon_truth: conditions and comparisons use EPSILON = 1e-10: #if (1e-11) is false, 0.1+0.2 = 0.3 is true, 1 = 1+1e-11 is true
// POV-Ray 3.7: no warning. Effect: red sphere only
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#if (1e-11) sphere { 0, 1.5 pigment { rgb <0,0,1> } } #end
#if ((0.1 + 0.2 = 0.3) & (1 = 1 + 1e-11) & !(1e-11)) sphere { 0, 1 pigment { rgb <1,0,0> } } #end
