// LENIENCY legacy_fog_bare_distance: fog { 3 rgb 1 }: a bare float is taken as the fog distance
// POV-Ray 3.7: Warning "Should use distance keyword." (level 150). Effect: red sphere in white fog
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
fog { 3 rgb <1,1,1> }
sphere { 0, 1 pigment { rgb <1,0,0> } }
