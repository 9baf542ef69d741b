// LENIENCY keyword_before_parenthesis: a keyword followed by a parenthesised value is the keyword and its value, never a call: after `angle 100` a cylinder camera's `location (<…> + <…>)` is the location (a call there read it as a second angle)
// POV-Ray 3.7: no warning. Effect: a red sphere through a cylinder camera moved by a sum
#version 3.7;
global_settings { assumed_gamma 1 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
camera { cylinder 1 angle 100 location (<0, 0, -4> + <0.5, 0, 0>) look_at (0 + <0.5, 0, 0>) }
sphere { 0, 1 pigment { rgb <1,0,0> } finish { phong (0.5) } }
