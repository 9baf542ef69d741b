// LENIENCY comma_diffuse_back: finish { diffuse A B }: a second float after diffuse (comma optional) is the back-side diffuse (Parse_Finish)
// POV-Ray 3.7: experimental-feature warning "backside illumination". Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { 0 1 pigment { rgb <1,0,0> } finish { diffuse 0.6 0.3 } }
