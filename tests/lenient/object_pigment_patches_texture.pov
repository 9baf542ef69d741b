// LENIENCY object_pigment_patches_texture: an object-level pigment{} after a plain texture{} modifies that texture in place (Parse_Object_Mods parse.cpp:7539-7574): the texture keeps its finish (ambient 1, diffuse 0) and only the pigment changes
// POV-Ray 3.7: no warning. Effect: flat, fully bright blue sphere (0,0,255): blue pigment with the red texture's ambient-1 finish
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { 0, 1 texture { pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } } pigment { rgb <0,0,1> } }
