// Still life with fruit, jade vase and brass candlestick
// POV-Ray 3.7 scene
#version 3.7;

global_settings { assumed_gamma 1.0 max_trace_level 6 }

#include "colors.inc"
#include "textures.inc"
#include "woods.inc"
#include "metals.inc"

camera {
  perspective
  location <0.4, 3.0, -7.2>
  look_at  <0.0, 1.05, 0.3>
  right    x*4/3
  up       y
  angle    40
}

// warm key light from upper left, cool fill from right
light_source { <-7, 9, -6> color rgb <1.0, 0.93, 0.82> }
light_source { <6, 5, -7> color rgb <0.25, 0.28, 0.35> }
light_source {
  <2.5, 7, -2>
  color rgb <0.7, 0.68, 0.6>
  spotlight
  point_at <0, 0.8, 0.5>
  radius 12
  falloff 28
  tightness 8
}

background { color rgb <0.05, 0.04, 0.03> }

// ---------------------------------------------------------------
// Table and back wall
// ---------------------------------------------------------------
box {
  <-6, -0.25, -3.5>, <6, 0, 4>
  texture { T_Wood10 scale 0.6 rotate y*90 finish { phong 0.4 phong_size 40 reflection 0.04 } }
}

// draped cloth along the back of the table
box {
  <-6, 0, 2.2>, <6, 0.03, 4>
  texture {
    pigment {
      checker color rgb <0.55, 0.08, 0.06>, color rgb <0.85, 0.8, 0.7>
      scale 0.3
    }
    normal { wrinkles 0.15 scale 0.2 }
    finish { diffuse 0.8 ambient 0.05 }
  }
}

plane {
  -z, -5
  texture {
    pigment {
      gradient x
      color_map {
        [0.00 color rgb <0.42, 0.36, 0.28>]
        [0.45 color rgb <0.42, 0.36, 0.28>]
        [0.50 color rgb <0.30, 0.25, 0.19>]
        [0.55 color rgb <0.42, 0.36, 0.28>]
        [1.00 color rgb <0.42, 0.36, 0.28>]
      }
      scale 0.8
    }
    normal { bumps 0.08 scale 0.05 }
    finish { ambient 0.08 diffuse 0.7 }
  }
}

// ---------------------------------------------------------------
// Jade vase
// ---------------------------------------------------------------
#declare Vase = union {
  sphere { <0, 0.75, 0>, 0.72 scale <1, 1.05, 1> }
  cone   { <0, 1.25, 0>, 0.45, <0, 1.95, 0>, 0.22 }
  cylinder { <0, 1.9, 0>, <0, 2.25, 0>, 0.24 }
  torus  { 0.26, 0.05 translate y*2.25 }
  cylinder { <0, 0, 0>, <0, 0.12, 0>, 0.45 }
  pigment { Jade scale 0.6 }
  finish { phong 0.9 phong_size 80 reflection 0.06 ambient 0.08 }
}
object { Vase translate <-1.9, 0, 1.2> }

// ---------------------------------------------------------------
// Marble cake stand with fruit
// ---------------------------------------------------------------
#declare Stand = union {
  cylinder { <0, 0, 0>, <0, 0.06, 0>, 0.55 }
  cone     { <0, 0.06, 0>, 0.25, <0, 0.55, 0>, 0.1 }
  cylinder { <0, 0.55, 0>, <0, 0.62, 0>, 1.15 }
  torus    { 1.15, 0.04 translate y*0.62 }
  texture {
    pigment { White_Marble scale 0.5 }
    finish { phong 0.7 reflection 0.08 }
  }
}

#macro Apple(Col, Pos, Rot)
  union {
    sphere { 0, 0.32 scale <1, 0.9, 1> }
    cylinder { <0, 0.2, 0>, <0.03, 0.4, 0>, 0.018
      pigment { color rgb <0.3, 0.2, 0.1> }
    }
    pigment {
      bozo
      color_map {
        [0.0 color Col]
        [0.7 color Col * 0.75]
        [1.0 color rgb <0.9, 0.75, 0.2>]
      }
      scale 0.08
    }
    normal { dents 0.15 scale 0.05 }
    finish { phong 0.6 phong_size 30 }
    rotate Rot
    translate Pos
  }
#end

#macro Grapes(Pos, Layers)
  union {
    #local L = 0;
    #while (L < Layers)
      #local N = Layers - L + 2;
      #local Rr = 0.05 + 0.035 * (Layers - L);
      #local I = 0;
      #while (I < N)
        #local Ang = I * 360 / N + L * 37;
        sphere {
          <Rr * cos(radians(Ang)), -L * 0.1, Rr * sin(radians(Ang))>, 0.075
        }
        #local I = I + 1;
      #end
      #local L = L + 1;
    #end
    cylinder { <0, 0, 0>, <0.05, 0.18, 0>, 0.015 pigment { color rgb <0.35, 0.3, 0.1> } }
    pigment { color rgb <0.28, 0.05, 0.3> }
    finish { phong 0.9 phong_size 60 ambient 0.06 }
    translate Pos
  }
#end

union {
  object { Stand }
  object { Apple(color rgb <0.7, 0.05, 0.03>, <-0.45, 0.93, -0.15>, <0, 20, 0>) }
  object { Apple(color rgb <0.45, 0.65, 0.1>, < 0.35, 0.93, -0.35>, <10, 70, 0>) }
  object { Apple(color rgb <0.75, 0.1, 0.05>, < 0.25, 0.93,  0.45>, <-8, 140, 5>) }
  object { Grapes(<-0.25, 1.32, 0.35>, 5) }
  // orange
  sphere {
    <0.0, 1.2, 0.05>, 0.3
    pigment { color rgb <0.95, 0.45, 0.05> }
    normal { dents 0.4 scale 0.012 }
    finish { phong 0.4 phong_size 20 }
  }
  translate <0.5, 0, 0.6>
}

// ---------------------------------------------------------------
// Brass candlestick with candle
// ---------------------------------------------------------------
#declare Candlestick = union {
  union {
    cylinder { <0, 0, 0>, <0, 0.08, 0>, 0.42 }
    torus    { 0.42, 0.04 translate y*0.08 }
    cone     { <0, 0.08, 0>, 0.18, <0, 0.4, 0>, 0.07 }
    sphere   { <0, 0.55, 0>, 0.14 }
    cylinder { <0, 0.5, 0>, <0, 1.4, 0>, 0.06 }
    torus    { 0.1, 0.03 translate y*1.0 }
    cone     { <0, 1.4, 0>, 0.06, <0, 1.55, 0>, 0.2 }
    torus    { 0.2, 0.025 translate y*1.55 }
    texture { T_Brass_3B }
  }
  cylinder {
    <0, 1.5, 0>, <0, 2.35, 0>, 0.11
    pigment { color rgb <0.95, 0.92, 0.8> }
    finish { diffuse 0.8 ambient 0.15 phong 0.2 }
  }
  cylinder { <0, 2.35, 0>, <0, 2.42, 0>, 0.008 pigment { Black } }
  sphere {
    0, 1 scale <0.035, 0.09, 0.035> translate <0, 2.5, 0>
    pigment { color rgb <1, 0.8, 0.3> }
    finish { ambient 1 diffuse 0 }
  }
}
object { Candlestick translate <2.1, 0, 1.1> }

// ---------------------------------------------------------------
// Small objects in front
// ---------------------------------------------------------------
// pink alabaster egg
sphere {
  0, 1 scale <0.24, 0.32, 0.24>
  texture { PinkAlabaster }
  translate <-0.6, 0.32, -1.0>
}

// lemon
sphere {
  0, 1 scale <0.36, 0.25, 0.25>
  pigment { color rgb <0.95, 0.85, 0.1> }
  normal { bumps 0.3 scale 0.02 }
  finish { phong 0.5 phong_size 25 }
  rotate y*-25
  translate <-1.5, 0.25, -0.6>
}

// candy cane stick lying on the table
cylinder {
  <-0.8, 0, 0>, <0.8, 0, 0>, 0.06
  pigment { Candy_Cane scale 0.12 }
  finish { phong 0.8 ambient 0.1 }
  rotate y*20
  translate <1.0, 0.06, -1.4>
}

// peeled orange rind spiral: ring of tori
#declare K = 0;
#while (K < 5)
  torus {
    0.18 - K * 0.02, 0.02
    pigment { color rgb <0.95, 0.5, 0.08> }
    finish { phong 0.3 }
    rotate x * (K * 8)
    translate <2.6 - K * 0.08, 0.03 + K * 0.02, -0.9>
  }
  #declare K = K + 1;
#end

// a cork coaster under the vase shadow
cylinder {
  <0, 0, 0>, <0, 0.03, 0>, 0.5
  texture { Cork }
  translate <-2.6, 0, -0.4>
}

// folded paper napkin: a flat triangle and a curled smooth_triangle flap
union {
  triangle { <-0.6, 0.005, -0.45>, <0.6, 0.005, -0.45>, <0.0, 0.005, 0.55> }
  smooth_triangle {
    <-0.6, 0.01, -0.45>, <0.2, 1, -0.1>,
    <0.6, 0.01, -0.45>, <-0.2, 1, -0.1>,
    <0.0, 0.22, -0.2>, <0, 0.6, -1>
  }
  texture {
    pigment {
      gradient x
      color_map {
        [0.0 color rgb <0.95, 0.93, 0.88>]
        [0.8 color rgb <0.95, 0.93, 0.88>]
        [0.8 color rgb <0.2, 0.35, 0.6>]
        [1.0 color rgb <0.2, 0.35, 0.6>]
      }
      scale 0.2
    }
    finish { diffuse 0.8 ambient 0.1 }
  }
  rotate y*15
  translate <-0.75, 0, -1.05>
}
