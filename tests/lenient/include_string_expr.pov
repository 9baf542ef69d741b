// LENIENCY include_string_expr: #include takes any string expression (concat(...), string identifier), may appear mid-object, and may supply half an object (the main file closes the brace)
// POV-Ray 3.7: no warning. Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare Base = "lenient_open";
#include concat(Base, "_sphere", ".inc")
  pigment { rgb <1,0,0> } }
