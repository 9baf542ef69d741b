// LENIENCY legacy_reflection_exponent: finish { reflection_exponent 2 } (old spelling of reflection { ... exponent }) and old-style "reflection 0.5"
// POV-Ray 3.7: no warning. Effect: reflective red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { 0, 1 pigment { rgb <1,0,0> } finish { reflection 0.5 reflection_exponent 2 } }
