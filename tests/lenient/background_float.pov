// LENIENCY background_float: background { 0.5 } = rgbft 0.5 (transmit 0.5); in 3.7 without alpha output the background is premultiplied by (1-transmit), giving 0.25 grey instead of 0.5
// POV-Ray 3.7: no warning. Effect: uniform grey 0.25 (sRGB ~137) instead of 0.5 (~188)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { 0.5 }
