// s9.pov -- "Bead track": a closed cubic-spline loop of beads on posts,
// coloured from a linear colour spline, with a quadratic-spline "snake".
#version 3.7;

#include "colors.inc"
#include "functions.inc"
#include "math.inc"
#include "transforms.inc"
#include "strings.inc"

global_settings { assumed_gamma 1.0 }

camera {
  location <0, 6.5, -9>
  look_at  <0, 0.8, 0>
  angle 48
}

light_source { <-8, 12, -10> color rgb 1.0 }
light_source { <10, 6, -4> color rgb 0.35 }

sky_sphere {
  pigment {
    gradient y
    color_map { [0 color rgb <0.9, 0.85, 0.8>] [0.4 color rgb <0.4, 0.6, 0.9>] }
  }
}

// ---------------------------------------------------------------
// Ground: pigment_pattern driving a texture_map, pattern functions
// ---------------------------------------------------------------
#declare F_Leo = function { pattern { leopard scale 0.35 } }
#declare F_Wav = function { pattern { waves frequency 2 scale 1.5 } }

plane { y, 0
  texture {
    pigment_pattern {
      function { clip(0.6 * F_Wav(x, 0, z) + 0.4 * f_wood(x * 0.3, z * 0.3, 0), 0, 1) }
    }
    texture_map {
      [0.0 pigment { color rgb <0.25, 0.45, 0.2> } normal { function { F_Leo(x, y, z) } 0.4 } finish { diffuse 0.8 }]
      [0.5 pigment { color rgb <0.45, 0.55, 0.25> } normal { function { F_Leo(x, y, z) } 0.4 } finish { diffuse 0.8 }]
      [0.5 pigment { color rgb <0.60, 0.50, 0.32> } finish { diffuse 0.7 }]
      [1.0 pigment { color rgb <0.72, 0.62, 0.42> } finish { diffuse 0.7 specular 0.2 }]
    }
  }
}

// ---------------------------------------------------------------
// Track path: closed cubic spline through control points in an array
// ---------------------------------------------------------------
#declare NP = 8;
#declare CP = array[NP] {
  <3.5, 1.2, 0>, <2.4, 2.0, 2.4>, <0, 1.0, 3.2>, <-2.6, 1.8, 2.2>,
  <-3.8, 1.0, 0>, <-2.4, 2.2, -2.2>, <0, 0.8, -2.6>, <2.6, 1.6, -2.0>
}

// build the spline with extra wrap-around points so it closes smoothly
#declare Track = spline {
  cubic_spline
  -1, CP[NP - 1]
  #for (I, 0, NP - 1)
    I, CP[I]
  #end
  NP,     CP[0]
  NP + 1, CP[1]
}

// colour along the loop: a linear spline of colours
#declare Col_Spl = spline {
  linear_spline
  0.0, <0.9, 0.15, 0.1>
  0.25, <0.95, 0.8, 0.1>
  0.5, <0.1, 0.7, 0.3>
  0.75, <0.15, 0.35, 0.95>
  1.0, <0.9, 0.15, 0.1>
}

// bead size modulation as a spline *function*
#declare F_Size = function {
  spline {
    natural_spline
    0.0, <0.16, 0, 0>
    0.3, <0.26, 0, 0>
    0.6, <0.12, 0, 0>
    1.0, <0.16, 0, 0>
  }
}

#macro Bead(Pos, Rad, Col)
  sphere { Pos, Rad
    pigment { color rgb Col }
    finish { specular 0.6 roughness 0.01 reflection 0.08 }
  }
#end

// macro that returns a value: tangent of a spline by central difference
#macro Spl_Tangent(Spl, T)
  vnormalize(Spl(T + 0.01) - Spl(T - 0.01))
#end

#declare NB = 96;
union {
  #for (I, 0, NB - 1)
    #declare T = I / NB;
    #declare Pos = Track(T * NP);
    #declare Rad = F_Size(T).x;
    Bead(Pos, Rad, Col_Spl(T))
  #end
}

// posts down to the ground every few beads, with a ring oriented along the tangent
#declare I = 0;
#while (I < NP * 2)
  #declare T = I / 2;
  #declare Pos = Track(T);
  #declare Tan = Spl_Tangent(Track, T);
  cylinder { <Pos.x, 0, Pos.z>, Pos - <0, 0.2, 0>, 0.05
    pigment { color rgb <0.35, 0.3, 0.28> }
    finish { specular 0.2 }
  }
  torus { 0.3, 0.04
    Reorient_Trans(y, Tan)
    translate Pos
    pigment { color rgb <0.85, 0.85, 0.9> }
    finish { metallic specular 0.7 roughness 0.01 reflection 0.2 }
  }
  #declare I = I + 1;
#end

// ---------------------------------------------------------------
// A snake following a quadratic spline, lying on the ground
// ---------------------------------------------------------------
#declare Snake = spline {
  quadratic_spline
  0.0, <-1.6, 0, -0.6>
  0.2, <-0.9, 0, 0.3>
  0.4, <-0.2, 0, -0.4>
  0.6, <0.5, 0, 0.4>
  0.8, <1.1, 0, -0.3>
  1.0, <1.6, 0, 0.2>
}

#declare F_Skin = function { pattern { hexagon scale 0.06 } }
#declare NS = 60;
#for (J, 0, NS)
  #declare S = 0.05 + 0.95 * J / NS;
  #declare R = 0.07 + 0.1 * sin(pi * S);
  sphere { Snake(S) + <0, R, -3.6>, R
    pigment {
      function { F_Skin(x, y, z) / 2 + 0.25 * S }
      color_map { [0 color rgb <0.2, 0.35, 0.05>] [0.5 color rgb <0.55, 0.6, 0.1>] [1 color rgb <0.9, 0.8, 0.3>] }
    }
    finish { specular 0.4 }
  }
#end

// Label made with strings.inc, as a debug message
#debug concat("s9: ", str(NB, 0, 0), " beads, track start ", VStr(Track(0)), "\n")

// central mound with a function normal
sphere { <0, -1.2, 0>, 2
  pigment { color rgb <0.6, 0.45, 0.3> }
  normal { function { f_noise3d(x * 4, y * 4, z * 4) } 0.8 }
  finish { diffuse 0.8 }
}
