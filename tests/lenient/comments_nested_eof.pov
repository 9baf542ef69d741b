// LENIENCY comments_nested_eof: block comments nest (/* /* */ */) and a // comment may end the file without a newline (Parse_C_Comments)
// POV-Ray 3.7: no warning. Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
/* outer /* inner */ still comment */
sphere { 0, 1 pigment { rgb <1,0,0> } } // trailing comment without newline