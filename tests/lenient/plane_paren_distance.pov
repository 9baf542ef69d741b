// LENIENCY plane_paren_distance: a parenthesised float directly after a vector: plane { z (3) } parses as normal z, distance 3 (the "(" is not a binary operator, so the vector ends; Parse_Comma finds no comma)
// POV-Ray 3.7: no warning. Effect: red plane filling the view
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
plane { z (3) pigment { rgb <1,0,0> } }
