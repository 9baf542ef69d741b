// LENIENCY colour_spelling_aliases: color/colour, color_map/colour_map, quick_color/quick_colour, fade_color/fade_colour, use_color/use_colour are the same tokens (only "gray" exists: .grey is an error)
// POV-Ray 3.7: no warning. Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare C = rgb <0.2,0.4,0.6>;
#debug concat("gray=", str(C.gray, 0, 3), "\n")
sphere { 0, 1 pigment { gradient x colour_map { [0 colour rgb <1,0,0>] [1 color rgb <1,0,0>] } quick_colour rgb 1 }
  interior { fade_colour rgb 1 } }
