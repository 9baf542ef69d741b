// LENIENCY comma_function_params: user function declared with parameter names without commas, function(a b c), and called from SDL without commas, F(0.5 0.25 2) (FNCode::Parameter, Parse_Function_Call)
// POV-Ray 3.7: no warning. Effect: red sphere of radius F(...)=1
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare F = function(a b c) { a + b*c }
sphere { 0 F(0.5 0.25 2) pigment { rgb <1,0,0> } }
