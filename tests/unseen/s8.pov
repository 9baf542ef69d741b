// s8.pov -- "Mossy boulder": a noisy isosurface rock with pebbles and
// mushrooms scattered on its surface via trace(), positions cached in a file.
#version 3.7;

#include "colors.inc"
#include "functions.inc"
#include "rand.inc"
#include "transforms.inc"

global_settings { assumed_gamma 1.0 max_trace_level 6 }

camera {
  location <0, 3.2, -6.5>
  look_at  <0, 0.6, 0>
  angle 50
}

light_source { <-6, 9, -7> color rgb <1.0, 0.97, 0.9> }
light_source { <5, 4, -3> color rgb <0.35, 0.4, 0.5> shadowless }

background { color rgb <0.55, 0.7, 0.9> }

// ---------------------------------------------------------------
// Ground plane with a function normal built from f_ripples
// ---------------------------------------------------------------
plane { y, -1
  pigment { checker color rgb <0.45, 0.38, 0.28> color rgb <0.38, 0.32, 0.22> scale 0.75 }
  normal { function { f_ripples(x*0.8, y, z*0.8) } 0.35 }
  finish { diffuse 0.8 ambient 0.05 }
}

// ---------------------------------------------------------------
// The boulder: a sphere function disturbed by noise
// ---------------------------------------------------------------
#declare Rock_R   = 1.6;
#declare Bump_Amt = 0.45;

#declare F_Rock = function(x, y, z) {
  f_sphere(x, y*1.25, z, Rock_R)
  - Bump_Amt * (f_noise3d(x*1.7, y*1.7, z*1.7) - 0.5)
  - 0.08 * f_granite(x*0.6, y*0.6, z*0.6)
}

// A pigment function used as a mask for the moss
#declare P_Moss = function {
  pigment {
    bozo
    color_map { [0.0 rgb 0] [0.45 rgb 0] [0.65 rgb 1] [1.0 rgb 1] }
    scale 0.45
  }
}

#declare Rock = isosurface {
  function { F_Rock(x, y, z) }
  contained_by { box { <-2.4, -1.6, -2.4>, <2.4, 2.0, 2.4> } }
  threshold 0
  accuracy 0.001
  max_gradient 3.5
  pigment {
    // moss only on the upper, mask-enabled part of the rock
    function { min(1, max(0, P_Moss(x, y, z).gray * (0.3 + 0.7 * max(0, y / 1.3)))) }
    color_map {
      [0.00 color rgb <0.42, 0.40, 0.37>]
      [0.30 color rgb <0.50, 0.48, 0.44>]
      [0.55 color rgb <0.30, 0.42, 0.15>]
      [1.00 color rgb <0.18, 0.36, 0.08>]
    }
  }
  normal { granite 0.25 scale 0.6 }
  finish { diffuse 0.75 specular 0.1 roughness 0.05 }
  translate <0, 0.2, 0>
}

object { Rock }

// ---------------------------------------------------------------
// Decorations: macros that return objects
// ---------------------------------------------------------------
#macro Mushroom(Size, CapHue)
  union {
    cylinder { <0, 0, 0>, <0, 0.8, 0>, 0.12 pigment { rgb <0.95, 0.92, 0.85> } }
    sphere { <0, 0.75, 0>, 0.4 scale <1, 0.55, 1>
      pigment {
        spotted
        color_map {
          [0.0 color CapHue]
          [0.7 color CapHue]
          [0.75 color White]
          [1.0 color White]
        }
        scale 0.12
      }
    }
    finish { specular 0.3 }
    scale Size
  }
#end

#macro Pebble(Size, Tint)
  sphere { 0, 1
    scale <1, 0.6, 0.85> * Size
    pigment { Tint }
    finish { specular 0.4 roughness 0.02 }
  }
#end

// ---------------------------------------------------------------
// Scatter: shoot rays at the rock from random directions, record hits
// ---------------------------------------------------------------
#declare S = seed(2718);
#declare Data_File = "s8_points.txt";

#fopen Out Data_File write
#declare Count = 0;
#declare Tries = 0;
#while (Count < 40 & Tries < 400)
  #declare Dir = VRand_On_Sphere(S);
  // only the upper hemisphere, tilted toward the camera
  #if (Dir.y > 0.1 & Dir.z < 0.4)
    #declare From = Dir * 4 + <0, 0.2, 0>;
    #declare Norm = <0, 0, 0>;
    #declare Hit = trace(Rock, From, -Dir, Norm);
    #if (vlength(Norm) != 0)
      #declare Kind = mod(Count, 3);
      #write (Out, Hit, ", ", Norm, ", ", Kind, ",\n")
      #declare Count = Count + 1;
    #end
  #end
  #declare Tries = Tries + 1;
#end
#fclose Out

#debug concat("s8: wrote ", str(Count, 0, 0), " hit points\n")

// Read them back and place decorations with #switch
#declare Caps = array[3] { color rgb <0.85, 0.1, 0.05>, color rgb <0.9, 0.55, 0.1>, color rgb <0.6, 0.2, 0.5> };
#declare Idx = 0;
#fopen In Data_File read
#while (defined(In))
  #read (In, P, N, K)
  #switch (K)
    #case (0)
      object { Mushroom(RRand(0.25, 0.45, S), Caps[mod(div(Idx, 3), 3)])
        Reorient_Trans(y, N)
        translate P
      }
    #break
    #case (1)
      object { Pebble(RRand(0.08, 0.16, S), color rgb <0.7, 0.65, 0.6> + 0.2 * VRand(S))
        Reorient_Trans(y, N)
        translate P
      }
    #break
    #else
      sphere { P, 0.07
        pigment { color rgb <1, 0.9, 0.2> }
        finish { ambient 0.4 diffuse 0.6 }
      }
  #end
  #declare Idx = Idx + 1;
#end

// A ring of stones around the boulder, placed by tracing down onto the ground
#declare Ground = plane { y, -1 }
#for (I, 0, 17)
  #declare A = I * 20 + RRand(-5, 5, S);
  #declare R0 = 2.6 + RRand(-0.2, 0.3, S);
  #declare Start = vrotate(<R0, 3, 0>, <0, A, 0>);
  #declare GN = <0, 0, 0>;
  #declare GP = trace(Ground, Start, -y, GN);
  #if (vlength(GN) > 0)
    object { Pebble(RRand(0.15, 0.3, S), color rgb <0.55, 0.55, 0.6>)
      rotate y * A
      translate GP + <0, 0.05, 0>
    }
  #end
#end
