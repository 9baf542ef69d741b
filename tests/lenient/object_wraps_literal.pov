// LENIENCY object_wraps_literal: object { } may wrap a literal object, not only an identifier
// POV-Ray 3.7: no warning. Effect: red sphere shifted right by 0.5
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
object { sphere { 0, 1 } pigment { rgb <1,0,0> } translate x*0.5 }
