// LENIENCY color_float_is_rgbft: color 0.8 (bare float after color / colour / in pigment) is promoted to ALL FIVE components: rgbft <0.8,0.8,0.8,0.8,0.8>, i.e. very transparent
// POV-Ray 3.7: no warning. Effect: dark, see-through sphere (compare rgb_float); #debug prints the 5 components
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare C = color 0.8;
#debug concat("C=", vstr(5, C, ",", 0, 2), "\n")
sphere { 0, 1 pigment { color 0.8 } }
