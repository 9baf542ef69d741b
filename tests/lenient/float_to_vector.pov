// LENIENCY float_to_vector: a float where a vector is expected fills every component (Parse_Num_Factor copies the value into all *Terms slots): scale 0.8, translate -0.25, rotate 30 = <30,30,30>, sphere centre 0
// POV-Ray 3.7: no warning. Effect: red box rotated about all three axes
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
box { -0.7, 0.7 scale 0.8 rotate 30 translate -0.25 translate 0.25 pigment { rgb <1,0,0> } }
