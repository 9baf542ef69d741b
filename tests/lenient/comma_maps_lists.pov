// LENIENCY comma_maps_lists: color_map entries [value colour] without comma; checker colour list without comma (Parse_Colour_Map, Parse_Blend_List)
// POV-Ray 3.7: no warning. Effect: red/blue gradient plane behind a red/blue checkered sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
plane { z 1 pigment { gradient x color_map { [0 rgb <1,0,0>] [0.5 rgb <0,0,1>] [1 rgb <1,0,0>] } scale 2 } }
sphere { 0 1 pigment { checker rgb <1,0,0> rgb <0,0,1> scale 0.5 } }
