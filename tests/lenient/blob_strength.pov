// LENIENCY blob_strength: blob components' strengths without a comma or the word strength, and components made in a #while inside the blob
// POV-Ray 3.7: no warning (renders as trace does: tests/lenient/povray/blob_strength.png)
#version 3.7;
#include "lenient_hdr.inc"
blob { threshold 0.6
  sphere { <0,1,0> 0.8 1 scale 1.2 }
  #declare I = 0;
  #while (I < 3)
    sphere { <I-1, 0.3, 0>, 0.7, 1 }
    #declare I = I + 1;
  #end
  pigment { rgb <1,0.3,0.2> } }
