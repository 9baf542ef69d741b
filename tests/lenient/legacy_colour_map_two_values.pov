// LENIENCY legacy_colour_map_two_values: old color_map entry form [v1 v2 color C1 color C2] (two values, two colours; the second "color" keyword is required) in Parse_Colour_Map
// POV-Ray 3.7: no warning. Effect: plane with red-blue-red gradient
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
plane { z, 1 pigment { gradient x color_map { [0.0 0.5 color rgb <1,0,0> color rgb <0,0,1>] [0.5 1.0 color rgb <0,0,1> color rgb <1,0,0>] } scale 2 } }
