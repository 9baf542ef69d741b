// LENIENCY comma_spline: spline entries "t <v>" without commas and with a trailing comma (Parse_Spline)
// POV-Ray 3.7: experimental-feature warning "spline" only. Effect: red sphere at Sp(0.5) = <0,0,0>
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare Sp = spline { linear_spline 0 <-1,0,0> 1 <1,0,0> 2 <1,1,0>, }
sphere { Sp(0.5) 0.5 pigment { rgb <1,0,0> } }
