// LENIENCY empty_blocks: empty global_settings {}, finish {}, interior {} are silently accepted (note: normal {} is a fatal "No normal type given", pigment {} only warns, texture {} adds a default black layer)
// POV-Ray 3.7: no warning. Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
global_settings { }
sphere { 0, 1 pigment { rgb <1,0,0> } finish { } interior { } }
