// LENIENCY lathe_macro: a lathe's last point followed by a macro call that leaves a transformation
// POV-Ray 3.7: no warning (renders as trace does: tests/lenient/povray/lathe_macro.png)
#version 3.7;
#include "lenient_hdr.inc"
#macro Move() translate <0, 0.2, 0> #end
#declare T = transform { rotate y*30 }
lathe { linear_spline 4, <0,0>, <1,0.5>, <0.6,1.5>, <0,2> Move() pigment { rgb <0.9,0.7,0.2> } }
