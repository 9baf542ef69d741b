// LENIENCY macro_opens: a macro that opens a block another macro closes; #break out of a #while
// POV-Ray 3.7: no warning (renders as trace does: tests/lenient/povray/macro_opens.png)
#version 3.7;
#include "lenient_hdr.inc"
#macro Open() union { #end
#macro Close() pigment { rgb <0.5,1,0.5> } } #end
Open()
  sphere { <-1,1,0>, 0.7 }
  sphere { <1,1,0>, 0.7 }
Close()
#declare N = 0;
#while (1)
  #declare N = N + 1;
  #if (N > 3) #break #end
  box { <N-3, 0, 1>, <N-2.5, 0.3, 1.5> pigment { rgb 1 } }
#end
