// LENIENCY macro_params: a macro's parameter list with a comma missing: #macro Ball(LOC, R, COL, TRANS FIN)
// POV-Ray 3.7: no warning (renders as trace does: tests/lenient/povray/macro_params.png)
#version 3.7;
#include "lenient_hdr.inc"
#macro Ball(LOC, R, COL, TRANS FIN)
  sphere { LOC, R pigment { COL transmit TRANS } finish { FIN } }
#end
#declare F = finish { phong 1 }
Ball(<0,1,0>, 1, rgb <1,0.5,0>, 0.3 F)
