// LENIENCY local_at_top_level: #local outside any macro or include file declares into the current (global) table, silently
// POV-Ray 3.7: no warning. Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#local R = 1;
sphere { 0, R pigment { rgb <1,0,0> } }
