// LENIENCY sweep_macro: a declared union whose sphere_sweep takes its points from a loop calling a macro, used with object { U }
// POV-Ray 3.7: no warning (renders as trace does: tests/lenient/povray/sweep_macro.png)
#version 3.7;
#include "lenient_hdr.inc"
#macro P(I) <I-1.5, 1 + 0.5*sin(I*2), 0>, 0.2 #end
#declare U = union {
  sphere_sweep { linear_spline 4,
    #for (I, 0, 3) P(I) #end
    pigment { rgb <0,0.7,1> } }
  sphere { <0,0,0>, 0.3 pigment { rgb 1 } }
}
object { U }
