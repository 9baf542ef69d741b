// LENIENCY version_expression_and_include: #version takes a float expression; a #version inside an include file is NOT undone when the include ends
// POV-Ray 3.7: end-of-parse warning "language version set to 3.1 or earlier" (because of the include). Effect: red sphere; #debug prints 3.70 then 3.10
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#version 3.0 + 0.7;
#debug concat("version=", str(version, 0, 2), "\n")
#include "lenient_ver31.inc"
#debug concat("after include version=", str(version, 0, 2), "\n")
sphere { 0, 1 pigment { rgb <1,0,0> } }
