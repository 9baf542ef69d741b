// LENIENCY declare_layered_texture: #declare T = texture {...} texture {...} (several textures after one "=") declares a layered texture (Parse_RValue TEXTURE_TOKEN loop, parse.cpp:8677-8705)
// POV-Ray 3.7: no warning. Effect: red sphere under a half-transparent blue layer (magenta-ish)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare T = texture { pigment { rgb <1,0,0> } } texture { pigment { rgbt <0,0,1,0.5> } }
sphere { 0, 1 texture { T } }
