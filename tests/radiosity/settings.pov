// Radiosity through rad_def.inc's settings (a #switch inside the block), lit only by a glowing
// panel (emission), with a mirror ball, a bumpy floor seen with `normal on`, a back-lit
// screen (diffuse_back), an object radiosity rays do not see (no_radiosity) and a box that
// few of a sample's rays go on from (importance 0.4).
// Needs POV-Ray's include files installed.
#version 3.7;
#include "rad_def.inc"
global_settings { assumed_gamma 1.0 radiosity { Rad_Settings(Radiosity_Fast, on, off) } }
camera { location <0, 1.4, -3.8> look_at <0, 1, 0> angle 62 }
#declare Grey = texture { pigment { rgb 0.75 } finish { diffuse 0.7 } }
plane { y, 0 texture { pigment { checker rgb 0.8 rgb 0.5 scale 0.5 }
                       normal { bumps 0.4 scale 0.2 } finish { diffuse 0.7 } } }
plane { y, 2.6 texture { Grey } }
plane { z, 2 texture { Grey } }
plane { x, -2 texture { pigment { rgb <0.2, 0.3, 0.8> } finish { diffuse 0.7 } } }
plane { x, 2 texture { Grey } }
plane { z, -4 texture { Grey } }
box { <-0.6, 2.55, -0.6>, <0.6, 2.6, 0.6> texture { pigment { rgb 1 } finish { emission 6 diffuse 0 } } }
sphere { <0.7, 0.45, 0.3>, 0.45 texture { pigment { rgb 0.1 } finish { reflection 0.8 diffuse 0.2 } } }
box { <-1.2, 0, 0.8>, <-0.3, 0.9, 1.2> texture { pigment { rgb <0.9, 0.6, 0.1> } finish { diffuse 0.8 } }
      radiosity { importance 0.4 } }
polygon { 4, <-0.2, 0.2>, <0.3, 0.2>, <0.3, 1.0>, <-0.2, 1.0> translate z*1.6
          texture { pigment { rgb 0.9 } finish { diffuse 0.5, 0.4 } } }
sphere { <-1.4, 1.6, -1>, 0.3 no_radiosity texture { pigment { rgb <1, 0, 0> } finish { emission 4 } } }
