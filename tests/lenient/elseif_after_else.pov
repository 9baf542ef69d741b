// LENIENCY elseif_after_else: #elseif after #else is accepted when the #if branch was taken (the rest is skipped in SKIP_TIL_END_COND); a second #else is likewise accepted. (If the #if branch is false both are "Mis-matched" errors)
// POV-Ray 3.7: no warning. Effect: red sphere (first branch)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#if (1)
  sphere { 0, 1 pigment { rgb <1,0,0> } }
#else
  sphere { 0, 1 pigment { rgb <0,0,1> } }
#elseif (1)
  sphere { 0, 1 pigment { rgb <0,1,0> } }
#else
  sphere { 0, 1 pigment { rgb <0,1,1> } }
#end
