// LENIENCY rgb_four_components: rgb <1,0,0,0.5> (4 terms after rgb): accepted, the 4th value becomes FILTER
// POV-Ray 3.7: Warning "Suspicious expression after rgb.". Effect: half-filtering red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { 0, 1 pigment { rgb <1,0,0,0.5> } }
