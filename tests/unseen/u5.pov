// Table setting with glass and metal objects
// wine glass and cup are built as smooth_triangle meshes of revolution
// POV-Ray 3.7 scene
#version 3.7;

global_settings { assumed_gamma 1.0 max_trace_level 8 }

#include "colors.inc"
#include "textures.inc"
#include "glass.inc"
#include "metals.inc"
#include "golds.inc"
#include "woods.inc"

camera {
  location <0.5, 3.4, -6.5>
  look_at  <0.2, 0.9, 0.5>
  right    x*4/3
  up       y
  angle    40
}

light_source { <-5, 8, -4> color rgb <1, 0.96, 0.9> }
light_source { <6, 6, -6> color rgb 0.35 }
light_source {
  <1, 9, 3>
  color rgb 0.5
  spotlight
  point_at <0, 0, 0.5>
  radius 10
  falloff 20
}

// ---------------------------------------------------------------
// Room: table top and a draped backdrop
// ---------------------------------------------------------------
box {
  <-5, -0.3, -3>, <5, 0, 4>
  texture { T_Wood28 scale 0.5 rotate y*90 finish { phong 0.5 phong_size 50 reflection 0.08 } }
}

plane {
  -z, -6
  pigment {
    gradient x
    color_map {
      [0.0 color rgb <0.25, 0.05, 0.08>]
      [0.5 color rgb <0.45, 0.1, 0.12>]
      [1.0 color rgb <0.25, 0.05, 0.08>]
    }
    scale 0.7
  }
  normal { waves 0.6 frequency 1.4 scale <0.7, 1, 1> }
  finish { ambient 0.1 diffuse 0.6 specular 0.2 roughness 0.05 }
}

background { color rgb <0.02, 0.02, 0.03> }

// ---------------------------------------------------------------
// Surface of revolution as a smooth_triangle mesh
// Kind 0: wine glass bowl outside, 1: bowl inside, 2: metal cup wall
// ---------------------------------------------------------------
#macro Prof(Kind, T)
  #if (Kind = 0)
    #local PP = <0.06 + 0.5 * pow(sin(T * pi * 0.6), 0.8), 0.9 + 1.0 * T, 0>;
  #else
    #if (Kind = 1)
      #local PP = <0.03 + 0.47 * pow(sin(T * pi * 0.6), 0.8), 0.96 + 0.94 * T, 0>;
    #else
      #local PP = <0.32 + 0.1 * T + 0.04 * sin(T * pi), 0.05 + 0.75 * T, 0>;
    #end
  #end
  PP
#end

#macro ProfN(Kind, T)
  #local E = 0.001;
  #local D = Prof(Kind, min(T + E, 1)) - Prof(Kind, max(T - E, 0));
  #local Nn = <D.y, -D.x, 0>;
  (Nn / vlength(Nn))
#end

#macro RevPoint(Kind, T, A)
  #local P = Prof(Kind, T);
  <P.x * cos(A), P.y, P.x * sin(A)>
#end

#macro RevNormal(Kind, T, A)
  #local N = ProfN(Kind, T);
  <N.x * cos(A), N.y, N.x * sin(A)>
#end

#macro RevMesh(Kind, NU, NV)
  mesh {
    #local J = 0;
    #while (J < NV)
      #local T0 = J / NV;
      #local T1 = (J + 1) / NV;
      #local I = 0;
      #while (I < NU)
        #local A0 = 2 * pi * I / NU;
        #local A1 = 2 * pi * (I + 1) / NU;
        smooth_triangle {
          RevPoint(Kind, T0, A0), RevNormal(Kind, T0, A0),
          RevPoint(Kind, T0, A1), RevNormal(Kind, T0, A1),
          RevPoint(Kind, T1, A1), RevNormal(Kind, T1, A1)
        }
        smooth_triangle {
          RevPoint(Kind, T0, A0), RevNormal(Kind, T0, A0),
          RevPoint(Kind, T1, A1), RevNormal(Kind, T1, A1),
          RevPoint(Kind, T1, A0), RevNormal(Kind, T1, A0)
        }
        #local I = I + 1;
      #end
      #local J = J + 1;
    #end
  }
#end

// ---------------------------------------------------------------
// Materials
// ---------------------------------------------------------------
#declare M_ClearGlass = material {
  texture {
    pigment { color rgbf <0.98, 0.99, 1.0, 0.95> }
    finish { F_Glass4 }
  }
  interior { I_Glass1 }
}

#declare M_BottleGlass = material {
  texture {
    pigment { color Col_Glass_Winebottle }
    finish { F_Glass3 }
  }
  interior { I_Glass }
}

// ---------------------------------------------------------------
// Wine glass
// ---------------------------------------------------------------
#declare WineGlass = union {
  object { RevMesh(0, 28, 14) }
  object { RevMesh(1, 28, 14) }
  torus { 0.525, 0.012 translate y*1.9 }
  cylinder { <0, 0.02, 0>, <0, 0.95, 0>, 0.05 }
  cylinder { <0, 0, 0>, <0, 0.03, 0>, 0.42 }
  torus { 0.42, 0.015 translate y*0.015 }
  material { M_ClearGlass }
}
object { WineGlass translate <-1.3, 0, 0.6> }

// ---------------------------------------------------------------
// Wine bottle
// ---------------------------------------------------------------
union {
  cylinder { <0, 0, 0>, <0, 1.6, 0>, 0.38 }
  sphere { <0, 1.6, 0>, 0.38 scale <1, 0.9, 1> translate y*0.16 }
  cone { <0, 1.8, 0>, 0.25, <0, 2.4, 0>, 0.13 }
  cylinder { <0, 2.35, 0>, <0, 2.9, 0>, 0.13 }
  torus { 0.13, 0.025 translate y*2.88 }
  material { M_BottleGlass }
  translate <-2.3, 0, 2.0>
}

// ---------------------------------------------------------------
// Silver cup, gilded inside (interior_texture on an open mesh)
// ---------------------------------------------------------------
union {
  object {
    RevMesh(2, 32, 8)
    texture { T_Chrome_4B }
    interior_texture { T_Gold_3C }
  }
  torus { 0.42 + 0.04, 0.025 translate y*0.8 texture { T_Chrome_4B } }
  cylinder { <0, 0, 0>, <0, 0.05, 0>, 0.33 texture { T_Chrome_4B } }
  torus { 0.2, 0.035 rotate x*90 translate <0.48, 0.45, 0> texture { T_Chrome_4B } }
  rotate y*200
  translate <0.9, 0, 0.9>
}

// ---------------------------------------------------------------
// Copper pot, brass ball, ruby glass ball
// ---------------------------------------------------------------
union {
  cylinder { <0, 0, 0>, <0, 0.7, 0>, 0.6 }
  torus { 0.6, 0.04 translate y*0.7 }
  sphere { 0, 1 scale <0.6, 0.08, 0.6> translate y*0.72 }
  sphere { <0, 0.83, 0>, 0.07 }
  torus { 0.12, 0.03 rotate x*90 translate <0.7, 0.5, 0> }
  torus { 0.12, 0.03 rotate x*90 translate <-0.7, 0.5, 0> }
  texture { T_Copper_2C }
  translate <2.8, 0, 2.2>
}

sphere {
  <2.2, 0.35, -0.4>, 0.35
  texture { T_Brass_3A }
}

sphere {
  <-0.2, 0.3, -1.0>, 0.3
  texture { T_Ruby_Glass }
  interior { I_Glass }
}

// ---------------------------------------------------------------
// Gold ring and a stack of coins
// ---------------------------------------------------------------
torus {
  0.18, 0.035
  texture { T_Gold_1D }
  rotate z*8
  translate <0.6, 0.035, -1.3>
}

#for (C, 0, 6)
  cylinder {
    <0, C * 0.045, 0>, <0, C * 0.045 + 0.04, 0>, 0.16
    texture { T_Gold_4B normal { radial 0.3 frequency 40 } }
    translate <1.35 + 0.02 * sin(C * 2), 0, -0.9 + 0.015 * cos(C * 3)>
  }
#end

// ---------------------------------------------------------------
// Cut crystal: octahedron mesh in lead glass
// ---------------------------------------------------------------
#declare Crystal = mesh {
  triangle { < 1, 0, 0>, <0, 0,  1>, <0,  1.4, 0> }
  triangle { <0, 0,  1>, <-1, 0, 0>, <0,  1.4, 0> }
  triangle { <-1, 0, 0>, <0, 0, -1>, <0,  1.4, 0> }
  triangle { <0, 0, -1>, < 1, 0, 0>, <0,  1.4, 0> }
  triangle { < 1, 0, 0>, <0, 0,  1>, <0, -1.4, 0> }
  triangle { <0, 0,  1>, <-1, 0, 0>, <0, -1.4, 0> }
  triangle { <-1, 0, 0>, <0, 0, -1>, <0, -1.4, 0> }
  triangle { <0, 0, -1>, < 1, 0, 0>, <0, -1.4, 0> }
  texture { T_Glass3 }
  interior { I_Glass2 }
}
object { Crystal scale 0.28 rotate <0, 30, 12> translate <-1.35, 0.4, -1.1> }

// a silver spoon: flattened sphere bowl and a thin handle
union {
  sphere { 0, 1 scale <0.18, 0.04, 0.12> }
  cylinder { <0.15, 0.02, 0>, <0.9, 0.05, 0>, 0.025 }
  texture { Silver_Texture }
  rotate y*-35
  translate <-0.5, 0.04, -1.5>
}
