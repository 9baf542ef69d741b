// LENIENCY legacy_tiles: texture { tiles { texture {...} tile2 texture {...} } } (pre-3.0 checker of textures) is still parsed silently (Parse_Tiles)
// POV-Ray 3.7: no warning. Effect: red/blue checkered plane
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
plane { z, 1 texture { tiles { texture { pigment { rgb <1,0,0> } } tile2 texture { pigment { rgb <0,0,1> } } } scale 0.5 } }
