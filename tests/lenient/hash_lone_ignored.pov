// LENIENCY hash_lone_ignored: a "#" followed by a token that is not a directive keyword is silently dropped (Parse_Directive OTHERWISE branch ungets the token): "#sphere {...}", "# }"
// POV-Ray 3.7: no warning. Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#sphere { 0, 1 pigment { rgb <1,0,0> } # }
#
