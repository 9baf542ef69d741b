// LENIENCY semicolon_optional_v30: with #version 3.0 a float #declare without ";" is silent
// POV-Ray 3.7: only the end-of-parse "language version set to 3.1 or earlier" warning. Effect: red sphere
#version 3.0;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare R = 1
sphere { 0, R pigment { rgb <1,0,0> } }
