// LENIENCY if_unbalanced_braces: conditional branches need not be brace-balanced: each branch closes the sphere itself
// POV-Ray 3.7: no warning. Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { 0, 1
#if (1)
  pigment { rgb <1,0,0> } }
#else
  pigment { rgb <0,0,1> } }
#end
