// LENIENCY default_without_hash: top-level "default {...}" without "#" is silently accepted (Parse_Frame DEFAULT_TOKEN case calls Parse_Default directly)
// POV-Ray 3.7: no warning. Effect: sphere uses the default red pigment
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
default { pigment { rgb <1,0,0> } }
sphere { 0, 1 }
