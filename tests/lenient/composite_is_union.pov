// LENIENCY composite_is_union: legacy keyword composite is parsed as union
// POV-Ray 3.7: Warning "Use union instead of composite.". Effect: two red spheres
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
composite { sphere { -x, 0.8 } sphere { x, 0.8 } pigment { rgb <1,0,0> } }
