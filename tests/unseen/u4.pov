// Mountain lake landscape with cloudy sky, haze, pine trees and a cabin
// POV-Ray 3.7 scene
#version 3.7;

global_settings { assumed_gamma 1.0 max_trace_level 5 }

#include "colors.inc"
#include "textures.inc"
#include "skies.inc"
#include "stones.inc"
#include "woods.inc"

camera {
  location <0, 6.5, -8>
  look_at  <0, 5, 30>
  right    x*4/3
  up       y
  angle    60
}

// sun, low in the west behind the camera
light_source { <-400, 350, -500> color rgb <1.0, 0.95, 0.85> }
// sky fill
light_source { <200, 300, 100> color rgb <0.2, 0.24, 0.3> }

sky_sphere { S_Cloud2 }

fog {
  distance 320
  color rgbt <0.78, 0.82, 0.9, 0.3>
}

// ---------------------------------------------------------------
// Ground and rolling hills
// ---------------------------------------------------------------
#declare Grass = texture {
  pigment {
    granite
    color_map {
      [0.0 color rgb <0.18, 0.35, 0.08>]
      [0.5 color rgb <0.28, 0.45, 0.12>]
      [1.0 color rgb <0.45, 0.5, 0.2>]
    }
    turbulence 0.5
    scale 4
  }
  normal { bumps 0.5 scale 0.15 }
  finish { ambient 0.1 diffuse 0.7 }
}

plane { y, 0 texture { Grass } }

#declare H = 0;
#while (H < 5)
  sphere {
    0, 1
    scale <18 + 4 * H, 3 + mod(H, 3), 12>
    translate <-40 + H * 20, -1.2, 45 + 6 * mod(H * 3, 4)>
    texture { Grass scale 2 }
  }
  #declare H = H + 1;
#end

// ---------------------------------------------------------------
// Mountains: cones with rock to snow texture_map
// ---------------------------------------------------------------
#declare Mountain = texture {
  gradient y
  texture_map {
    [0.00 T_Grnt7 scale 0.05 normal { crackle 0.8 scale 0.04 turbulence 0.5 }]
    [0.55 T_Grnt15 scale 0.05 normal { crackle 0.6 scale 0.04 turbulence 0.5 }]
    [0.68 pigment { color rgb <0.95, 0.97, 1.0> } finish { ambient 0.2 diffuse 0.8 } ]
    [1.00 pigment { color rgb <1, 1, 1> } finish { ambient 0.2 diffuse 0.8 } ]
  }
  warp { turbulence 0.15 octaves 4 }
}

#macro Peak(Pos, Hgt, Rad, Rot)
  cone {
    <0, 0, 0>, Rad, <0, Hgt, 0>, 0
    texture { Mountain scale <1, Hgt, 1> }
    rotate y*Rot
    translate Pos
  }
#end

Peak(<-55, 0, 110>, 40, 45, 0)
Peak(<-15, 0, 130>, 55, 50, 30)
Peak(< 30, 0, 115>, 45, 40, 60)
Peak(< 70, 0, 135>, 38, 45, 10)

// ---------------------------------------------------------------
// The lake
// ---------------------------------------------------------------
disc {
  <0, 0.03, 0>, y, 1
  scale <22, 1, 9>
  translate <2, 0, 18>
  texture {
    pigment { color rgbf <0.15, 0.3, 0.4, 0.3> }
    normal { ripples 0.35 frequency 6 scale 3 turbulence 0.2 }
    finish {
      ambient 0.05
      diffuse 0.3
      specular 0.8
      roughness 0.003
      reflection { 0.15, 0.9 fresnel on }
    }
  }
  interior { ior 1.33 }
}

// shore stones
#for (R, 0, 9)
  sphere {
    0, 1
    scale <0.5 + 0.1 * mod(R, 3), 0.3 + 0.05 * mod(R, 4), 0.45>
    rotate y*(R * 47)
    translate <-8 + R * 1.7, 0.05, 10.2 - 0.6 * mod(R * 7, 5) / 4>
    texture { T_Stone7 scale 0.4 }
  }
#end

// ---------------------------------------------------------------
// Pine trees
// ---------------------------------------------------------------
#declare Needles = texture {
  pigment {
    bozo
    color_map {
      [0.0 color rgb <0.05, 0.2, 0.06>]
      [1.0 color rgb <0.1, 0.32, 0.1>]
    }
    scale 0.2
  }
  normal { wrinkles 0.8 scale 0.1 }
  finish { ambient 0.08 diffuse 0.7 }
}

#macro Pine(Pos, Hgt)
  union {
    cylinder { <0, 0, 0>, <0, Hgt * 0.35, 0>, Hgt * 0.04 pigment { Tom_Wood scale 0.1 } }
    cone { <0, Hgt * 0.20, 0>, Hgt * 0.28, <0, Hgt * 0.60, 0>, 0 texture { Needles } }
    cone { <0, Hgt * 0.40, 0>, Hgt * 0.22, <0, Hgt * 0.80, 0>, 0 texture { Needles } }
    cone { <0, Hgt * 0.60, 0>, Hgt * 0.15, <0, Hgt * 1.00, 0>, 0 texture { Needles } }
    translate Pos
  }
#end

// deterministic scatter of trees on both sides of the lake
#declare T = 0;
#while (T < 28)
  #declare U = abs(sin(T * 12.9898) * 43758.5453);
  #declare U = U - floor(U);
  #declare V = abs(sin(T * 78.233) * 12345.6789);
  #declare V = V - floor(V);
  #if (mod(T, 2) = 0)
    #declare Tx = -30 + U * 15;
  #else
    #declare Tx = 17 + U * 15;
  #end
  #declare Tz = 5 + V * 35;
  object { Pine(<Tx, 0, Tz>, 4 + 5 * V) }
  #declare T = T + 1;
#end

// ---------------------------------------------------------------
// Log cabin with a mesh roof
// ---------------------------------------------------------------
#declare CabinW = 3;
#declare CabinD = 2.4;
#declare CabinH = 1.8;
#declare RoofH  = 1.2;

#declare Roof = mesh {
  triangle { <-0.2, CabinH, -0.2>, <CabinW + 0.2, CabinH, -0.2>, <CabinW + 0.2, CabinH + RoofH, CabinD / 2> }
  triangle { <-0.2, CabinH, -0.2>, <CabinW + 0.2, CabinH + RoofH, CabinD / 2>, <-0.2, CabinH + RoofH, CabinD / 2> }
  triangle { <-0.2, CabinH, CabinD + 0.2>, <CabinW + 0.2, CabinH, CabinD + 0.2>, <CabinW + 0.2, CabinH + RoofH, CabinD / 2> }
  triangle { <-0.2, CabinH, CabinD + 0.2>, <CabinW + 0.2, CabinH + RoofH, CabinD / 2>, <-0.2, CabinH + RoofH, CabinD / 2> }
  // gables
  triangle { <0, CabinH, 0>, <0, CabinH, CabinD>, <0, CabinH + RoofH, CabinD / 2> }
  triangle { <CabinW, CabinH, 0>, <CabinW, CabinH, CabinD>, <CabinW, CabinH + RoofH, CabinD / 2> }
  texture {
    pigment {
      gradient y
      color_map {
        [0.0 color rgb <0.35, 0.12, 0.08>]
        [0.8 color rgb <0.35, 0.12, 0.08>]
        [0.8 color rgb <0.2, 0.07, 0.05>]
        [1.0 color rgb <0.2, 0.07, 0.05>]
      }
      scale 0.15
    }
    finish { ambient 0.1 }
  }
}

union {
  // log walls
  #for (Lg, 0, 8)
    cylinder { <-0.1, Lg * 0.2 + 0.1, 0>, <CabinW + 0.1, Lg * 0.2 + 0.1, 0>, 0.1 }
    cylinder { <-0.1, Lg * 0.2 + 0.1, CabinD>, <CabinW + 0.1, Lg * 0.2 + 0.1, CabinD>, 0.1 }
    cylinder { <0, Lg * 0.2 + 0.1, -0.1>, <0, Lg * 0.2 + 0.1, CabinD + 0.1>, 0.1 }
    cylinder { <CabinW, Lg * 0.2 + 0.1, -0.1>, <CabinW, Lg * 0.2 + 0.1, CabinD + 0.1>, 0.1 }
  #end
  object { Roof }
  // door and window
  box { <1.2, 0, -0.12>, <1.8, 1.2, -0.1> pigment { DMFWood4 scale 2 } }
  box { <0.3, 0.8, -0.12>, <0.8, 1.3, -0.1> pigment { color rgb <1, 0.8, 0.4> } finish { ambient 0.8 } }
  // chimney
  box { <2.3, 1.8, 0.7>, <2.7, 3.3, 1.1> texture { T_Stone1 scale 0.3 } }
  texture { T_Wood3 scale 0.4 }
  rotate y*-20
  translate <-12, 0, 14>
}

// a small jetty into the lake
union {
  #for (P, 0, 6)
    box { <P * 0.45, 0.25, -0.6>, <P * 0.45 + 0.4, 0.32, 0.6> }
  #end
  #for (P, 0, 3)
    cylinder { <P * 1.0, -0.5, -0.55>, <P * 1.0, 0.35, -0.55>, 0.06 }
    cylinder { <P * 1.0, -0.5, 0.55>, <P * 1.0, 0.35, 0.55>, 0.06 }
  #end
  texture { T_Wood20 scale 0.3 }
  rotate y*-70
  translate <-4, 0, 9.5>
}
