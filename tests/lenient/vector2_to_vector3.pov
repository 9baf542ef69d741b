// LENIENCY vector2_to_vector3: a 2-component vector where a 3-vector is expected is padded with 0 (Parse_Vector zero-initialises Express): sphere { <0,0>, 1 } and translate <-1,0>
// POV-Ray 3.7: no warning. Effect: red sphere shifted left by 1
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { <0,0>, 1 translate <-1,0> pigment { rgb <1,0,0> } }
