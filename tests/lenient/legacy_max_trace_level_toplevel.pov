// LENIENCY legacy_max_trace_level_toplevel: max_trace_level outside global_settings (pre-3.0 placement) still sets the limit
// POV-Ray 3.7: Possible Parse Error "'max_trace_level' should be in global_settings block. ..." and Possible Parse Error "'max_trace_level' should be in 'global_settings{...}' statement.". Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
max_trace_level 3
sphere { 0, 1 pigment { rgb <1,0,0> } }
