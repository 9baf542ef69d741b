// LENIENCY include_in_declare: "#declare R = #include "file" ;" works: the include is spliced into the token stream at the RValue position; also the file name may omit the extension (Locate_File tries ".inc")
// POV-Ray 3.7: no warning. Effect: red sphere of radius 1
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare R = #include "lenient_one"
;
sphere { 0, R pigment { rgb <1,0,0> } }
