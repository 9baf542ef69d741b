// LENIENCY max_min_single_arg: max(), min(), bitwise_and/or/xor() accept a single argument (the comma loop is optional); their commas are otherwise required
// POV-Ray 3.7: no warning. Effect: red sphere of radius max(1)+min(0)+bitwise_or(0) = 1
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare R = max(1) + min(0) + bitwise_or(0);
sphere { 0, R pigment { rgb <1,0,0> } }
