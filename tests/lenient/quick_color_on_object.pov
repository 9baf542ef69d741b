// LENIENCY quick_color_on_object: a colour directly in an object ("sphere { ... color red 1 }") is parsed and discarded (used only for #version < 1.5)
// POV-Ray 3.7: Warning "Quick color belongs in texture. Color ignored.". Effect: blue sphere (the red quick colour is ignored)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { 0, 1 color red 1 pigment { rgb <0,0,1> } }
