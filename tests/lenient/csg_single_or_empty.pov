// LENIENCY csg_single_or_empty: union with one child or none is accepted
// POV-Ray 3.7: Warning "Should have at least 2 objects in csg." (twice). Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
union { sphere { 0, 1 } pigment { rgb <1,0,0> } }
union { }
