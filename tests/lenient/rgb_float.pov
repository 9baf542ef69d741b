// LENIENCY rgb_float: rgb 0.8 is promoted to rgb <0.8,0.8,0.8> (3 terms, no filter/transmit)
// POV-Ray 3.7: no warning. Effect: opaque light-grey sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { 0, 1 pigment { rgb 0.8 } }
