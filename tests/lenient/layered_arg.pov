// LENIENCY layered_arg: textures layered (texture {...} texture {...}) passed as one macro argument
// POV-Ray 3.7: no warning (renders as trace does: tests/lenient/povray/layered_arg.png)
#version 3.7;
#include "lenient_hdr.inc"
#macro Thing(T, P) sphere { P, 1 texture { T } } #end
#declare L = texture { pigment { rgb <0.2,0.2,1> } } texture { pigment { checker rgbt <1,1,1,1>, rgb <1,1,0> scale 0.3 } };
Thing(texture { pigment { rgb <0.2,0.2,1> } } texture { pigment { checker rgbt <1,1,1,1>, rgb <1,0,0> scale 0.3 } }, <-1.1,1,0>)
object { Thing(L, <1.1,1,0>) }
