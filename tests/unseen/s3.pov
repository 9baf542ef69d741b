// s3: blob creatures (sphere/cylinder components, negative strength, transformed components) and a row of superellipsoids
#version 3.7;
#include "colors.inc"
#include "textures.inc"
#include "metals.inc"

global_settings { assumed_gamma 1.0 }

camera {
  perspective
  location <0, 4.2, -11>
  look_at <0, 1.2, 0>
  angle 50
}

light_source { <-8, 12, -10> color rgb 1.0 }
light_source { <6, 8, -6> color rgb 0.45
  spotlight point_at <0, 0, 0> radius 25 falloff 40 tightness 5 }
light_source { <0, 6, 8> color rgb 0.25 shadowless }

background { color rgb <0.45, 0.6, 0.9> }

// marble-tiled floor
plane { y, 0
  texture {
    pigment { checker
      pigment { marble turbulence 0.6 color_map { [0 color rgb 0.95] [0.8 color rgb 0.75] [1 color rgb 0.4] } scale 0.6 }
      pigment { color rgb <0.35, 0.2, 0.15> }
      scale 1.5 }
    finish { diffuse 0.75 specular 0.3 reflection 0.15 }
  }
}

// Blob 1: a "molecule" of sphere components with a negative dimple
blob {
  threshold 0.6
  sphere { <0, 0, 0>, 1.2, 1.0 }
  sphere { <0.9, 0.3, 0>, 0.9, 1.0 }
  sphere { <-0.8, 0.5, 0.2>, 0.8, 1.0 }
  sphere { <0, 1.0, -0.2>, 0.8, 1.0 }
  sphere { <0.1, 0.4, -0.9>, 0.6, -1.5 }    // negative component carves a dent
  texture { pigment { color rgb <0.9, 0.25, 0.2> } finish { phong 0.8 phong_size 60 reflection 0.1 } }
  translate <-3.0, 1.1, 0.5>
}

// Blob 2: a dumbbell from a cylinder component and two spheres, with a scaled and rotated component
blob {
  threshold 0.5
  cylinder { <-1.2, 0, 0>, <1.2, 0, 0>, 0.5, 2.0 }
  sphere { <-1.3, 0, 0>, 0.8, 2.0 }
  sphere { <1.3, 0, 0>, 0.8, 2.0 }
  sphere { <0, 0, 0>, 0.6, 2.0 scale <1, 2.0, 1> rotate <0, 0, 30> }
  texture { T_Gold_3C }
  rotate <0, -25, 0>
  translate <0.3, 1.0, 1.8>
}

// Blob 3: a ring of spheres built in a loop, with a tilted cylinder through it
blob {
  threshold 0.65
  #for (I, 0, 7)
    sphere { <1.0, 0, 0>, 0.7, 1.0 rotate <0, I*45, 0> }
  #end
  cylinder { <0, -0.9, 0>, <0, 0.9, 0>, 0.3, 1.2 rotate <0, 0, 20> }
  texture { pigment { color rgb <0.2, 0.55, 0.9> } finish { specular 0.6 roughness 0.02 reflection 0.15 } }
  scale 0.9
  rotate <-20, 0, 0>
  translate <3.1, 1.1, 0.4>
}

// A row of superellipsoids with various exponents, each on a small chrome plinth
#macro Plinth(Pos)
  box { <-0.5, 0, -0.5>, <0.5, 0.2, 0.5>
    texture { T_Chrome_2A }
    translate Pos
  }
#end

#macro SuperE(Pos, E, N, Col)
  Plinth(Pos)
  superellipsoid { <E, N>
    texture { pigment { color Col } finish { phong 0.7 phong_size 40 reflection 0.05 } }
    scale 0.5
    rotate <0, 30, 0>
    translate Pos + <0, 0.7, 0>
  }
#end

SuperE(<-3.2, 0, -2.4>, 0.1, 0.1, rgb <0.95, 0.6, 0.1>)
SuperE(<-1.6, 0, -2.4>, 0.5, 0.5, rgb <0.3, 0.8, 0.3>)
SuperE(< 0.0, 0, -2.4>, 1.0, 1.0, rgb <0.6, 0.3, 0.8>)
SuperE(< 1.6, 0, -2.4>, 2.0, 0.5, rgb <0.9, 0.9, 0.2>)
SuperE(< 3.2, 0, -2.4>, 0.3, 2.5, rgb <0.2, 0.75, 0.75>)

// small pebbles along the back, placed with a #while loop
#declare K = 0;
#while (K < 9)
  sphere { <-4 + K, 0.15, 3.0 + 0.3*mod(K, 2)>, 0.15 + 0.03*mod(K, 3)
    pigment { color rgb <0.5 + 0.05*K, 0.45, 0.4> } finish { phong 0.4 } }
  #declare K = K + 1;
#end

// one large, flattened, tilted superellipsoid at the back
superellipsoid { <0.25, 0.75>
  texture { pigment { wood turbulence 0.1 color_map { [0 color rgb <0.7, 0.45, 0.2>] [1 color rgb <0.45, 0.25, 0.1>] } scale 0.15 rotate <90, 0, 0> }
            finish { specular 0.3 } }
  scale <3.2, 1.4, 0.3>
  rotate <0, 0, 4>
  translate <0, 1.4, 5.0>
}
