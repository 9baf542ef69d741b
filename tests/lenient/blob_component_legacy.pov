// LENIENCY blob_component_legacy: old blob syntax "component strength, radius, <centre>" is still accepted silently (commas optional)
// POV-Ray 3.7: no warning. Effect: red two-lobed blob
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
blob { threshold 0.5
  component 1 1 <-0.6,0,0>
  component 1, 1, <0.6,0,0>
  pigment { rgb <1,0,0> } }
