// LENIENCY switch_fallthrough: #case without #break falls through into the next #case body (like C)
// POV-Ray 3.7: no warning. Effect: red sphere and green sphere (case 2 body runs), blue not drawn
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare V = 1;
#switch (V)
  #case (1) sphere { 0, 1 pigment { rgb <1,0,0> } }
  #case (2) sphere { x*1.5, 0.5 pigment { rgb <0,1,0> } }
  #break
  #case (3) sphere { -x*1.5, 0.5 pigment { rgb <0,0,1> } }
#end
