// LENIENCY blob_strength_no_keyword: blob sphere { centre radius strength }: commas optional and the "strength" keyword optional (ALLOW(STRENGTH_TOKEN)); a negative strength needs a comma or parentheses ("1 -1" would be 0)
// POV-Ray 3.7: no warning. Effect: red two-lobed blob
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
blob { threshold 0.5
  sphere { <-0.6,0,0> 1 1 }
  sphere { <0.6,0,0>, 1, strength 1 }
  cylinder { <0,-1,0> <0,1,0> 0.2 (-0.5) }
  pigment { rgb <1,0,0> } }
