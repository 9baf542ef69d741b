// LENIENCY color_vector3: color <1,0,0> (3-vector where a 5-term colour is expected) is padded with zeros: filter = transmit = 0
// POV-Ray 3.7: no warning. Effect: opaque red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { 0, 1 pigment { color <1,0,0> } }
