// LENIENCY light_filter_ignored: light_source colour with a filter component (RGB-only context, Parse_Colour(RGBColour))
// POV-Ray 3.7: Warning "Expected pure RGB color expression, unexpected filter component will have no effect.". Effect: red sphere, fully lit
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
background { rgb 0.2 }
light_source { <0,0,-5> rgbf <1,1,1,0.5> }
sphere { 0, 1 pigment { rgb <1,0,0> } }
