// s10.pov -- "Valley with a stone ring": function height_field terrain,
// trees dropped onto it with trace(), an f_torus isosurface monument.
#version 3.7;

#include "colors.inc"
#include "functions.inc"
#include "rand.inc"
#include "shapes.inc"
#include "transforms.inc"
#include "math.inc"

global_settings { assumed_gamma 1.0 }

camera {
  location <0, 5.5, -10.5>
  look_at  <0, 0.6, 0>
  angle 55
}

light_source { <-20, 25, -15> color rgb <1, 0.95, 0.85> }
light_source { <15, 10, -20> color rgb <0.25, 0.3, 0.4> shadowless }

sky_sphere {
  pigment {
    function { max(0, y) }
    color_map { [0 color rgb <0.85, 0.8, 0.75>] [0.5 color rgb <0.45, 0.6, 0.85>] [1 color rgb <0.2, 0.35, 0.7>] }
  }
}

// ---------------------------------------------------------------
// Terrain: height_field built from a user function
// ---------------------------------------------------------------
#declare F_Valley = function(u, v) {
  // a valley running along v, plus rolling noise
  0.55 * pow(abs(u - 0.5) * 2, 1.6)
}
#declare F_Terrain = function(x, y, z) {
  min(1, max(0,
    0.1 + F_Valley(x, y)
    + 0.35 * (f_noise3d(x * 6, y * 6, 0.5) - 0.5)
    + 0.08 * (f_noise3d(x * 20, y * 20, 3.1) - 0.5)
  ))
}

#declare Terrain = height_field {
  function 160, 160 { F_Terrain(x, y, z) }
  smooth
  translate <-0.5, 0, -0.5>
  scale <16, 3, 16>
}

// pigment function to paint grass / rock / snow by height and a granite mask
#declare P_Mask = function { pigment { granite color_map { [0 rgb 0] [1 rgb 1] } scale 2 } }

object { Terrain
  pigment {
    function { min(1, max(0, y / 3 + 0.25 * (P_Mask(x, y, z).red - 0.5))) }
    color_map {
      [0.00 color rgb <0.30, 0.45, 0.15>]
      [0.35 color rgb <0.40, 0.50, 0.20>]
      [0.45 color rgb <0.45, 0.40, 0.32>]
      [0.75 color rgb <0.55, 0.52, 0.50>]
      [0.80 color rgb <0.95, 0.95, 0.97>]
      [1.00 color rgb <1, 1, 1>]
    }
  }
  finish { diffuse 0.85 }
}

#declare T_Min = min_extent(Terrain);
#declare T_Max = max_extent(Terrain);
#debug concat("s10: terrain extents ", vstr(3, T_Min, ", ", 0, 2), " .. ", vstr(3, T_Max, ", ", 0, 2), "\n")

// water in the valley bottom
plane { y, 0.35
  pigment { color rgbf <0.2, 0.4, 0.6, 0.4> }
  finish { reflection 0.3 specular 0.6 roughness 0.01 }
  normal { function { f_ripples(x, 0, z) } 0.2 scale 0.4 }
}

// ---------------------------------------------------------------
// Scatter trees: random points in the terrain box, dropped by trace()
// ---------------------------------------------------------------
#declare Clearing = sphere { <0, 0.8, -1>, 2.2 }   // keep the monument area free
#declare R = seed(1234);
#declare Data_File = "s10_points.txt";

#fopen TF Data_File write
#declare N = 0;
#for (I, 1, 220)
  #declare Pt = VRand_In_Box(<T_Min.x + 0.5, 0, T_Min.z + 0.5>, <T_Max.x - 0.5, 0, T_Max.z - 0.5>, R);
  #declare Start = <Pt.x, T_Max.y + 1, Pt.z>;
  #declare Nrm = <0, 0, 0>;
  #declare Hit = trace(Terrain, Start, -y, Nrm);
  #if (vlength(Nrm) > 0 & Hit.y > 0.4 & Hit.y < 1.9 & Nrm.y > 0.75)
    #if (!inside(Clearing, Hit))
      #declare Kind = (Hit.y > 1.3 ? 2 : (rand(R) < 0.5 ? 0 : 1));
      #write (TF, Hit, ",", Kind, ",", RRand(0.6, 1.1, R), ",\n")
      #declare N = N + 1;
    #end
  #end
#end
#fclose TF
#debug concat("s10: ", str(N, 0, 0), " trees\n")

#macro Pine(H)
  union {
    cylinder { 0, y * 0.3 * H, 0.06 * H pigment { color rgb <0.35, 0.22, 0.12> } }
    cone { y * 0.2 * H, 0.35 * H, y * H, 0 pigment { color rgb <0.1, 0.32, 0.12> } }
  }
#end
#macro Broadleaf(H)
  union {
    cylinder { 0, y * 0.5 * H, 0.07 * H pigment { color rgb <0.4, 0.28, 0.16> } }
    sphere { y * 0.65 * H, 0.32 * H
      pigment { agate color_map { [0 color rgb <0.25, 0.5, 0.1>] [1 color rgb <0.45, 0.6, 0.15>] } scale 0.2 }
      normal { bumps 0.5 scale 0.05 }
    }
  }
#end
#macro Boulder(H)
  sphere { 0, 0.18 * H scale <1.3, 0.7, 1> pigment { granite color_map { [0 rgb 0.4] [1 rgb 0.7] } scale 0.3 } }
#end

#declare Trees = union {
  #fopen TR Data_File read
  #while (defined(TR))
    #read (TR, P, K, H)
    #switch (K)
      #case (0) object { Pine(H) rotate y * 360 * rand(R) translate P } #break
      #case (1) object { Broadleaf(H) translate P } #break
      #case (2) object { Boulder(H) rotate y * 360 * rand(R) translate P } #break
    #end
  #end
  finish { diffuse 0.8 }
}
object { Trees }

// ---------------------------------------------------------------
// Monument: isosurface torus with agate texture, stood upright with
// Center_Trans / Align_Trans and placed on the terrain via trace()
// ---------------------------------------------------------------
#declare F_Ring = function(x, y, z) {
  f_torus(x, y, z, 1.0, 0.22) + 0.06 * f_agate(x * 2, y * 2, z * 2) - 0.03
}
#declare Ring = isosurface {
  function { F_Ring(x, y, z) }
  contained_by { box { <-1.4, -0.4, -1.4>, <1.4, 0.4, 1.4> } }
  max_gradient 2.5
  accuracy 0.002
  pigment {
    agate
    color_map {
      [0.0 color rgb <0.55, 0.25, 0.15>]
      [0.5 color rgb <0.85, 0.6, 0.35>]
      [1.0 color rgb <0.45, 0.2, 0.1>]
    }
    scale 0.5
  }
  finish { specular 0.4 roughness 0.02 diffuse 0.8 }
}

// stand the ring up (torus axis y -> z), then put its bottom at the origin
#declare Ring_Up = object { Ring rotate x * 90 }
#declare Ring_Up = object { Ring_Up Center_Trans(Ring_Up, x + z) Align_Trans(Ring_Up, -y, <0, 0, 0>) }

#declare MN = <0, 0, 0>;
#declare MP = trace(Terrain, <0, 10, -1>, -y, MN);
#declare MP = (vlength(MN) > 0 ? MP : <0, 0.5, -1>);
object { Ring_Up translate MP - y * 0.1 }

// a plinth of stacked slabs below it, sizes from an array
#declare Slab = array[4] { 1.6, 1.3, 1.0, 0.7 }
#for (J, 0, 3)
  box { <-Slab[J], 0, -0.45>, <Slab[J], 0.12, 0.45>
    translate MP - y * (0.5 - 0.12 * J)
    pigment { color rgb <0.6, 0.58, 0.55> }
    finish { specular 0.2 }
  }
#end
