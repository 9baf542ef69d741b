// LENIENCY comparison_needs_parens: top-level float/vector expressions are Parse_Rel_Factor (+ - * / only); comparisons, & | and ?: need parentheses: "#declare B = (1 < 2);" works, "#declare B = 1 < 2;" is an error
// POV-Ray 3.7: no warning. Effect: red sphere of radius 1
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare B = (1 < 2);
#declare T = (B ? 1 : 0.2);
sphere { 0, T pigment { rgb <1,0,0> } }
