// LENIENCY light_without_colour: light_source { <pos> } with no colour at all: Parse_Colour finds nothing and leaves black, so the light contributes nothing
// POV-Ray 3.7: no warning. Effect: sphere shows only ambient (dark red)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
background { rgb 0.2 }
light_source { <-5,5,-5> }
sphere { 0, 1 pigment { rgb <1,0,0> } }
