// LENIENCY legacy_v10_no_arithmetic: with #version < 1.5, Parse_Float/Parse_Vector use Parse_Num_Factor only: no infix arithmetic (0.5 + 0.5 is an error), plain literals work; "color red 1" style colours
// POV-Ray 3.7: pre-3.7 gamma and "language version set to 3.1 or earlier" warnings. Effect: red sphere
#version 1.0;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { <0, 0, 0>, 1 pigment { color red 1 } }
