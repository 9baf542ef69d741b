// LENIENCY semicolon_rules_37: with #version 3.7: ";" required after float/vector/colour #declare; a second ";" is swallowed by the ALLOW(SEMI_COLON) in Parse_Declare; ";" optional after object, pigment, string, array declares
// POV-Ray 3.7: no warning. Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare R = 1;;
#declare S = sphere { 0, R }
#declare T = sphere { 0, R };
#declare P = pigment { rgb <1,0,0> }
#declare Str = "text"
object { T pigment { P } }
