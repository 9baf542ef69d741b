// LENIENCY plane_paren: a vector followed by a parenthesised float: plane { z (-6) } is the normal z and the distance -6
// POV-Ray 3.7: no warning (renders as trace does: tests/lenient/povray/plane_paren.png)
#version 3.7;
#include "lenient_hdr.inc"
plane { z (-6) pigment { checker rgb 1 rgb 0.5 } }
plane { y (-1) pigment { rgb <0.3,0.6,0.3> } }
sphere { <0,1,0>, 1 pigment { rgb <1,0,0> } }
