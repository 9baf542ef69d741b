// LENIENCY colour_component_keywords: colour keyword components may follow an rgb/colour-id/vector colour and override single channels, in any order: rgb <1,0,0> green 1 filter 0.25; color red 1 blue 0.5; "color" keyword optional
// POV-Ray 3.7: no warning. Effect: red sphere; #debug shows the components
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare D = rgb <1,0,0> green 1 filter 0.25;
#declare E = color red 1 blue 0.5;
#debug concat("D=", vstr(5, D, ",", 0, 2), " E=", vstr(5, E, ",", 0, 2), "\n")
sphere { 0, 1 pigment { color rgb 1 green 0 blue 0 } }
