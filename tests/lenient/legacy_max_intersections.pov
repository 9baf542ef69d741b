// LENIENCY legacy_max_intersections: max_intersections at top level and in global_settings is parsed and ignored
// POV-Ray 3.7: Warning "'max_intersections' is no longer needed and has no effect in POV-Ray 3.7 or later." (x2). Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
max_intersections 64
global_settings { max_intersections 64 }
sphere { 0, 1 pigment { rgb <1,0,0> } }
