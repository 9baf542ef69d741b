// LENIENCY macro_opens_block: macro bodies are replayed token by token, so one macro may open a block that another closes
// POV-Ray 3.7: no warning. Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#macro Open(R) sphere { 0, R #end
#macro Close() } #end
Open(1) pigment { rgb <1,0,0> } Close()
