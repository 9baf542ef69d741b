// LENIENCY empty_pigment: pigment { } is accepted with a warning; the pigment stays at the default (black)
// POV-Ray 3.7: Warning "Pigment type unspecified or not 1st item.". Effect: black sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { 0, 1 pigment { } }
