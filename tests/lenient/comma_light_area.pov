// LENIENCY comma_light_area: light_source location and colour without comma; area_light axes and sizes without commas; non-integer sizes truncated by (int)
// POV-Ray 3.7: no warning. Effect: sphere lit by a blue area light
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
background { rgb 0.2 }
light_source { <0,5,-5> rgb <0,0,1> area_light <1,0,0> <0,1,0> 2.9 2.2 }
sphere { 0 1 pigment { rgb 1 } }
