// LENIENCY else_between: an #else falling between an object's items
// POV-Ray 3.7: no warning (renders as trace does: tests/lenient/povray/else_between.png)
#version 3.7;
#include "lenient_hdr.inc"
#declare Shiny = 1;
sphere { <0,1,0>, 1
  pigment { rgb <0.8,0.2,0.2> }
#if (Shiny)
  finish { phong 1 reflection 0.2 }
#else
  finish { diffuse 0.9 }
#end
  scale 1.2
}
