// LENIENCY rgb_colour_id_keeps_ft: rgb C where C is a colour identifier with transmit: Terms becomes 5, all five components are copied (transmit kept)
// POV-Ray 3.7: Warning "Suspicious expression after rgb.". Effect: mostly transparent red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare C = rgbt <1,0,0,0.8>;
sphere { 0, 1 pigment { rgb C } }
