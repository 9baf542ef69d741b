// LENIENCY include_without_hash: top-level "include" without "#"
// POV-Ray 3.7: Warning "Should have '#' before 'include'.". Effect: red sphere (colour from colors.inc)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
include "colors.inc"
sphere { 0, 1 pigment { Red } }
