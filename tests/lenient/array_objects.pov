// LENIENCY array_objects: an array element holding an object standing alone as a statement (Cube[I] in a loop)
// POV-Ray 3.7: no warning (renders as trace does: tests/lenient/povray/array_objects.png)
#version 3.7;
#include "lenient_hdr.inc"
#declare Cube = array[3];
#for (I, 0, 2)
  #declare Cube[I] = box { -0.4, 0.4 translate <I*1.2-1.2, 1, 0> pigment { rgb <I/2, 1-I/2, 0.5> } }
#end
#for (I, 0, 2)
  Cube[I]
#end
