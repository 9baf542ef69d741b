// Material sample board: rows of balls on chrome pedestals
// back row: stones.inc, middle row: woods.inc, front row: textures.inc
// POV-Ray 3.7 scene
#version 3.7;

global_settings { assumed_gamma 1.0 max_trace_level 5 }

#include "colors.inc"
#include "textures.inc"
#include "stones.inc"
#include "woods.inc"
#include "metals.inc"

camera {
  location <0, 5.2, -9.5>
  look_at  <0, 0.6, 0.4>
  right    x*4/3
  up       y
  sky      <0.03, 1, 0>
  angle    44
}

light_source { <-8, 12, -10> color rgb <1, 0.97, 0.92> }
light_source { <10, 6, -6> color rgb <0.3, 0.32, 0.38> }

sky_sphere {
  pigment {
    gradient y
    color_map {
      [0.0 color rgb <0.55, 0.55, 0.6>]
      [0.3 color rgb <0.25, 0.3, 0.45>]
      [1.0 color rgb <0.05, 0.08, 0.2>]
    }
  }
}

// floor: granite tiles
plane {
  y, 0
  texture {
    checker
    texture { T_Grnt9 finish { phong 0.5 reflection 0.08 } }
    texture { T_Grnt5 finish { phong 0.5 reflection 0.08 } }
    scale 1.5
  }
}

// back wall
plane {
  -z, -5
  pigment {
    wrinkles
    color_map {
      [0.0 color rgb <0.35, 0.33, 0.3>]
      [1.0 color rgb <0.55, 0.52, 0.48>]
    }
    scale 0.5
  }
  finish { ambient 0.1 }
}

// ---------------------------------------------------------------
// Sample ball on a pedestal
// ---------------------------------------------------------------
#declare BallR = 0.42;
#declare PedestalTex = texture { T_Chrome_3C }

#macro Sample(Pos, Tex)
  union {
    cylinder { <0, 0, 0>, <0, 0.05, 0>, 0.38 }
    torus { 0.38, 0.03 translate y*0.05 }
    cylinder { <0, 0, 0>, <0, 0.35, 0>, 0.12 }
    torus { 0.15, 0.03 translate y*0.35 }
    texture { PedestalTex }
    translate Pos
  }
  sphere {
    <0, 0.35 + BallR, 0>, BallR
    texture { Tex }
    translate Pos
  }
#end

#macro Row(Z, Tex1, Tex2, Tex3, Tex4, Tex5, Tex6)
  #local Sp = 1.25;
  #local X0 = -2.5 * Sp;
  Sample(<X0 + 0 * Sp, 0, Z>, Tex1)
  Sample(<X0 + 1 * Sp, 0, Z>, Tex2)
  Sample(<X0 + 2 * Sp, 0, Z>, Tex3)
  Sample(<X0 + 3 * Sp, 0, Z>, Tex4)
  Sample(<X0 + 4 * Sp, 0, Z>, Tex5)
  Sample(<X0 + 5 * Sp, 0, Z>, Tex6)
#end

// back row: layered stone textures (scaled down to ball size)
#declare S1 = texture { T_Stone1  scale 0.4 }
#declare S2 = texture { T_Stone4  scale 0.4 }
#declare S3 = texture { T_Stone9  scale 0.4 }
#declare S4 = texture { T_Stone25 scale 0.8 }
#declare S5 = texture { T_Stone31 scale 0.8 }
#declare S6 = texture { T_Stone44 scale 0.8 }
Row(2.4, S1, S2, S3, S4, S5, S6)

// middle row: woods, rotated so the grain runs across the ball
#declare W1 = texture { T_Wood1  scale 0.3 rotate <0, 90, 20> }
#declare W2 = texture { T_Wood7  scale 0.3 rotate <10, 90, 0> }
#declare W3 = texture { T_Wood12 scale 0.3 rotate <0, 60, 30> }
#declare W4 = texture { T_Wood19 scale 0.3 rotate <90, 0, 0> }
#declare W5 = texture { T_Wood23 scale 0.3 rotate <0, 45, 0> }
#declare W6 = texture { T_Wood35 scale 0.3 rotate <20, 80, 0> }
Row(1.0, W1, W2, W3, W4, W5, W6)

// front row: classic textures.inc pigments and textures
#declare Gloss = finish { phong 0.7 phong_size 60 reflection 0.05 }
#declare P1 = texture { pigment { Jade scale 0.5 } finish { Gloss } }
#declare P2 = texture { pigment { Blue_Agate scale 0.4 } finish { Gloss } }
#declare P3 = texture { pigment { Sapphire_Agate scale 0.4 } finish { Gloss } }
#declare P4 = texture { pigment { Red_Marble scale 0.5 } finish { Gloss } }
#declare P5 = texture { pigment { Brown_Agate scale 0.4 } finish { Gloss } }
#declare P6 = texture { pigment { Blood_Marble scale 0.5 } finish { Gloss } }
Row(-0.4, P1, P2, P3, P4, P5, P6)

// two extra wood textures from textures.inc on blocks at the front
box {
  <-0.5, 0, -0.3>, <0.5, 0.3, 0.3>
  texture { Rosewood scale 0.3 }
  rotate y*15
  translate <-2.2, 0, -2.0>
}
box {
  <-0.5, 0, -0.3>, <0.5, 0.3, 0.3>
  texture { Sandalwood scale 0.3 }
  rotate y*-10
  translate <2.2, 0, -2.0>
}
// polished chrome and brass reference balls
sphere { <-0.6, 0.3, -2.0>, 0.3 texture { Polished_Chrome } }
sphere { < 0.6, 0.3, -2.0>, 0.3 texture { Brass_Texture } }
