// LENIENCY declare_without_hash: top-level "declare" without "#" (Parse_Frame DECLARE_TOKEN case -> Parse_Directive(false)); "local" without "#" is an error
// POV-Ray 3.7: Warning "Should have '#' before 'declare'." (level 295, so only for #version > 2.95) and, for #version >= 3.5, Possible Parse Error "'declare' should be changed to '#declare'.". Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
declare R = 1;
sphere { 0, R pigment { rgb <1,0,0> } }
