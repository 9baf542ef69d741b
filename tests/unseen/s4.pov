// s4: height-field landscape (plasma3.png smooth, fract003.png with water_level) by a lake, with conic/bezier prisms and a superellipsoid
#version 3.7;
#include "colors.inc"
#include "textures.inc"
#include "metals.inc"

global_settings { assumed_gamma 1.0 }

camera {
  perspective
  location <0, 4.5, -12>
  look_at <0.5, 1.2, 2>
  angle 60
}

light_source { <-30, 40, -25> color rgb <1.0, 0.95, 0.85> }
light_source { <20, 15, -30> color rgb <0.25, 0.3, 0.4> shadowless }

sky_sphere {
  pigment { gradient y
    color_map { [0 color rgb <0.85, 0.8, 0.75>] [0.25 color rgb <0.45, 0.6, 0.9>] [1 color rgb <0.15, 0.3, 0.7>] } }
}

// lake
plane { y, 0.3
  texture {
    pigment { color rgb <0.1, 0.25, 0.35> }
    normal { bumps 0.15 scale <2, 1, 0.6> }
    finish { diffuse 0.4 specular 0.6 roughness 0.01 reflection 0.35 }
  }
}

// Mountain range in the back: smooth plasma height field with altitude colouring
height_field {
  png "plasma3.png"
  smooth
  texture {
    pigment { gradient y
      color_map {
        [0.00 color rgb <0.35, 0.3, 0.2>]
        [0.30 color rgb <0.2, 0.45, 0.12>]
        [0.60 color rgb <0.3, 0.4, 0.2>]
        [0.75 color rgb <0.5, 0.45, 0.4>]
        [0.90 color rgb <0.95, 0.95, 1.0>]
        [1.00 color rgb <1.0, 1.0, 1.0>]
      }
    }
    finish { diffuse 0.85 }
  }
  translate <-0.5, 0, -0.5>
  rotate <0, 180, 0>
  scale <44, 8, 16>
  translate <0, -3.0, 17>
}

// Rugged island on the left: fract003 height field cut off below water_level
height_field {
  png "fract003.png"
  water_level 0.2
  texture {
    pigment { bozo turbulence 0.4
      color_map { [0 color rgb <0.45, 0.35, 0.2>] [0.5 color rgb <0.3, 0.45, 0.15>] [1 color rgb <0.55, 0.5, 0.4>] }
      scale 0.1 }
    finish { diffuse 0.8 }
  }
  translate <-0.5, 0, -0.5>
  scale <9, 1.8, 6>
  rotate <0, 25, 0>
  translate <-6.5, -0.2, 2.0>
}

// Stone plaza on the right shore
box { <0.5, 0, -4>, <6.5, 0.5, 3>
  texture { pigment { granite color_map { [0 color rgb 0.7] [1 color rgb 0.45] } scale 0.8 } finish { diffuse 0.8 } }
}

// Pyramid-like tower: conic_sweep prism (square base, tip at origin, flipped)
prism {
  conic_sweep
  linear_spline
  0.6, 1, 5,
  <1, 1>, <-1, 1>, <-1, -1>, <1, -1>, <1, 1>
  texture { pigment { color rgb <0.85, 0.75, 0.5> } finish { specular 0.3 } }
  rotate <180, 0, 0>
  translate <0, 1, 0>
  scale <1.2, 3.0, 1.2>
  translate <2.0, 0.5, 1.5>
}

// Second conic prism: a truncated hexagonal spire, copper
prism {
  conic_sweep
  linear_spline
  0.3, 1, 7,
  <1, 0>, <0.5, 0.866>, <-0.5, 0.866>, <-1, 0>, <-0.5, -0.866>, <0.5, -0.866>, <1, 0>
  texture { T_Copper_3C }
  rotate <180, 0, 0>
  translate <0, 1, 0>
  scale <0.6, 3.2, 0.6>
  translate <5.4, 0.5, 0.9>
}

// Bezier-spline prism: a rounded, leaf-shaped monument slab standing upright
prism {
  linear_sweep
  bezier_spline
  -0.15, 0.15, 8,
  <0, -1>, <1.2, -0.8>, <1.0, 0.8>, <0, 1.4>,
  <0, 1.4>, <-1.0, 0.8>, <-1.2, -0.8>, <0, -1>
  texture { pigment { marble turbulence 0.7 color_map { [0 color rgb <0.9, 0.9, 0.88>] [0.6 color rgb <0.6, 0.62, 0.7>] [1 color rgb <0.2, 0.25, 0.3>] } scale 0.4 }
            finish { specular 0.4 reflection 0.1 } }
  rotate <-90, 0, 0>
  scale 1.1
  rotate <0, -20, 0>
  translate <3.3, 1.6, -0.9>
}

// Superellipsoid boulder / bench on the plaza
superellipsoid { <0.3, 0.3>
  texture { pigment { color rgb <0.7, 0.2, 0.15> } finish { phong 0.6 reflection 0.08 } }
  scale <0.9, 0.35, 0.5>
  rotate <0, 15, 0>
  translate <1.7, 0.85, -2.9>
}

// chrome ball on a small cylinder post
cylinder { <4.7, 0.5, -3.2>, <4.7, 1.1, -3.2>, 0.12 texture { T_Chrome_3C } }
sphere { <4.7, 1.4, -3.2>, 0.35 texture { T_Chrome_3C } }
