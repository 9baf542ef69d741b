// LENIENCY comma_text_bicubic: text { ttf "font" "string" depth offset } and the 16 bicubic_patch control points without commas (Parse_TrueType, Parse_Bicubic_Patch)
// POV-Ray 3.7: no warning. Effect: red text "Hi" in front of a red curved patch
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
bicubic_patch { type 1 flatness 0.1 u_steps 3 v_steps 3
  <-1,-1,1> <-0.3,-1,1> <0.3,-1,1> <1,-1,1>
  <-1,-0.3,1> <-0.3,-0.3,0> <0.3,-0.3,0> <1,-0.3,1>
  <-1,0.3,1> <-0.3,0.3,0> <0.3,0.3,0> <1,0.3,1>
  <-1,1,1> <-0.3,1,1> <0.3,1,1> <1,1,1>
  pigment { rgb <1,0,0> } }
text { ttf "crystal.ttf" "Hi" 0.2 0 pigment { rgb <1,0,0> } translate <-0.7,-0.3,-1> }
