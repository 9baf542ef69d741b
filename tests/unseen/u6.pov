// Pattern showcase: a wall of sample spheres, each with a different
// pattern, wave type, warp or map; mapping warps on torus, box and disc below
// POV-Ray 3.7 scene
#version 3.7;

global_settings { assumed_gamma 1.0 max_trace_level 5 }

#include "colors.inc"
#include "textures.inc"
#include "stones.inc"
#include "metals.inc"
#include "woodmaps.inc"

camera {
  location <0, 1.5, -15>
  look_at  <0, -0.2, 0>
  right    x*4/3
  up       y
  angle    40
}

light_source { <-10, 14, -18> color rgb <1, 0.98, 0.94> }
light_source { <12, 4, -12> color rgb <0.35, 0.38, 0.45> }

background { color rgb <0.1, 0.1, 0.12> }

// ---------------------------------------------------------------
// Backdrop: average of three patterns, floor: texture_map
// ---------------------------------------------------------------
plane {
  -z, -3
  pigment {
    average
    pigment_map {
      [1 gradient x color_map { [0 color rgb 0.15] [1 color rgb 0.35] } scale 2]
      [1 gradient y color_map { [0 color rgb <0.2, 0.2, 0.3>] [1 color rgb 0.3] } scale 3]
      [2 bozo color_map { [0 color rgb 0.25] [1 color rgb 0.4] } scale 0.6]
    }
  }
  finish { ambient 0.15 diffuse 0.5 }
}

plane {
  y, -3.4
  texture {
    gradient x
    texture_map {
      [0.00 T_Grnt3 scale 0.2]
      [0.45 T_Grnt3 scale 0.2]
      [0.55 T_Grnt12 scale 0.2 finish { reflection 0.15 phong 0.6 }]
      [1.00 T_Grnt12 scale 0.2 finish { reflection 0.15 phong 0.6 }]
    }
    scale 3
  }
}

// ---------------------------------------------------------------
// Grid helper
// ---------------------------------------------------------------
#declare Cols = 6;
#declare Rows = 4;
#declare Sp = 1.15;
#declare BR = 0.48;
#declare Shine = finish { phong 0.5 phong_size 40 ambient 0.1 diffuse 0.75 }

#macro Ball(C, R, Tex)
  sphere {
    0, BR
    texture { Tex }
    translate <(C - (Cols - 1) / 2) * Sp, (Rows - 1 - R) * Sp - 0.4, 0>
  }
#end

#macro Cmap3(A, B, Cc)
  color_map { [0.0 color A] [0.5 color B] [1.0 color Cc] }
#end

// Row 0 ----------------------------------------------------------
Ball(0, 0, texture {
  pigment { agate agate_turb 0.6 frequency 2 Cmap3(rgb <0.9, 0.8, 0.6>, rgb <0.5, 0.25, 0.1>, rgb <0.95, 0.9, 0.8>) scale 0.4 }
  finish { Shine } })
Ball(1, 0, texture {
  pigment { boxed color_map { [0 color Navy] [0.5 color SkyBlue] [1 color White] } scale 0.15 translate <0.15, 0.15, 0.15> warp { repeat x*0.3 flip x } warp { repeat y*0.3 } warp { repeat z*0.3 offset x*0.15 } }
  finish { Shine } })
Ball(2, 0, texture {
  pigment { bozo turbulence 0.8 octaves 5 omega 0.6 lambda 2.5 Cmap3(rgb <0.1, 0.2, 0.5>, rgb <0.9, 0.9, 0.95>, rgb <0.1, 0.2, 0.5>) scale 0.3 }
  finish { Shine } })
Ball(3, 0, texture {
  pigment { brick color rgb 0.85, color rgb <0.6, 0.2, 0.1> brick_size <0.6, 0.25, 0.3> mortar 0.05 scale <0.3, 0.6, 1> warp { spherical orientation z dist_exp 0 } }
  finish { Shine } })
Ball(4, 0, texture {
  pigment { cells color_map { [0 color rgb <0.2, 0.6, 0.3>] [1 color rgb <0.9, 0.8, 0.2>] } scale 0.15 }
  finish { Shine } })
Ball(5, 0, texture {
  pigment { checker color Red, color White scale <0.125, 0.25, 1> warp { spherical orientation z dist_exp 0 } }
  finish { Shine } })

// Row 1 ----------------------------------------------------------
Ball(0, 1, texture {
  pigment { crackle color_map { [0 color Black] [0.05 color rgb <0.8, 0.6, 0.3>] [1 color rgb <0.6, 0.35, 0.15>] } scale 0.2 }
  normal { crackle 0.6 scale 0.2 }
  finish { Shine } })
Ball(1, 1, texture {
  pigment { cylindrical triangle_wave frequency 4 phase 0.2 Cmap3(rgb <0.9, 0.3, 0.1>, rgb <1, 0.9, 0.3>, rgb <0.3, 0.05, 0.05>) scale 0.5 rotate x*90 }
  finish { Shine } })
Ball(2, 1, texture {
  pigment { dents color_map { [0 color rgb <0.3, 0.3, 0.35>] [1 color rgb <0.8, 0.8, 0.9>] } scale 0.1 }
  normal { dents 0.9 scale 0.1 }
  finish { Shine } })
Ball(3, 1, texture {
  pigment { gradient y scallop_wave frequency 3 Cmap3(rgb <0.05, 0.3, 0.4>, rgb <0.4, 0.9, 0.8>, rgb <0.05, 0.3, 0.4>) warp { turbulence 0.4 octaves 3 } scale 0.8 }
  finish { Shine } })
Ball(4, 1, texture {
  pigment {
    granite
    pigment_map {
      [0.0 Jade scale 2]
      [0.5 White_Marble scale 2]
      [1.0 Sapphire_Agate scale 2]
    }
    scale 0.5
  }
  finish { Shine } })
Ball(5, 1, texture {
  pigment { hexagon color rgb <0.9, 0.7, 0.1>, color rgb <0.2, 0.15, 0.05>, color rgb <0.7, 0.35, 0.05> scale 0.08 rotate x*90 warp { cylindrical orientation y dist_exp 0 } }
  finish { Shine } })

// Row 2 ----------------------------------------------------------
Ball(0, 2, texture {
  leopard
  texture_map {
    [0.0 T_Copper_3C]
    [0.3 T_Copper_3C]
    [0.6 T_Gold_3C]
    [1.0 T_Gold_3C]
  }
  scale 0.12
})
Ball(1, 2, texture {
  pigment {
    marble
    turbulence 0.3
    Cmap3(rgb <0.95, 0.95, 0.9>, rgb <0.3, 0.3, 0.3>, rgb <0.95, 0.95, 0.9>)
    scale 0.4
    warp { black_hole <0, 0, 0>, 0.8 falloff 2 strength 1.5 }
  }
  finish { Shine } })
Ball(2, 2, texture {
  pigment { onion cubic_wave Cmap3(rgb <0.6, 0.1, 0.4>, rgb <1, 0.8, 0.9>, rgb <0.6, 0.1, 0.4>) scale 0.3 translate <0.3, 0.2, -0.5> }
  finish { Shine } })
Ball(3, 2, texture {
  pigment { planar poly_wave 2 frequency 3 Cmap3(rgb <0.1, 0.1, 0.4>, rgb <0.5, 0.7, 1>, rgb <1, 1, 1>) scale 0.5 }
  finish { Shine } })
Ball(4, 2, texture {
  pigment { quilted control0 0.2 control1 0.9 Cmap3(rgb <0.5, 0.05, 0.05>, rgb <0.95, 0.85, 0.8>, rgb <0.5, 0.05, 0.05>) scale 0.25 }
  normal { quilted 0.8 control0 0.2 control1 0.9 scale 0.25 }
  finish { Shine } })
Ball(5, 2, texture {
  pigment { radial frequency 8 ramp_wave Cmap3(rgb <0.1, 0.5, 0.1>, rgb <0.9, 1, 0.6>, rgb <0.1, 0.5, 0.1>) rotate x*90 warp { turbulence 0.2 } }
  finish { Shine } })

// Row 3 ----------------------------------------------------------
Ball(3, 3, texture {
  pigment { color rgb <0.2, 0.45, 0.8> }
  normal { ripples 0.8 frequency 3 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } scale 0.5 translate <-0.2, 0.3, -0.5> }
  finish { Shine } })
Ball(1, 3, texture {
  pigment { spherical sine_wave frequency 3 Cmap3(rgb <1, 1, 0.6>, rgb <0.9, 0.4, 0.1>, rgb <0.2, 0, 0.1>) scale 0.35 translate <0.2, 0.25, -0.4> }
  finish { Shine } })
Ball(2, 3, texture {
  pigment { spiral1 5 Cmap3(rgb <0.1, 0.1, 0.1>, rgb <1, 0.9, 0.1>, rgb <0.1, 0.1, 0.1>) rotate x*90 scale 0.4 }
  finish { Shine } })
Ball(0, 3, texture {
  pigment { spiral2 3 Cmap3(rgb <0.9, 0.2, 0.6>, rgb <0.2, 0.1, 0.5>, rgb <0.9, 0.2, 0.6>) rotate x*90 scale 0.4 }
  finish { Shine } })
Ball(4, 3, texture {
  pigment { spotted color_map { [0 color rgb <0.8, 0.75, 0.6>] [1 color rgb <0.4, 0.3, 0.2>] } scale 0.1 }
  normal {
    gradient y
    normal_map {
      [0.3 bumps 0.8 scale 0.05]
      [0.7 wrinkles 0.8 scale 0.1]
    }
    scale 0.5
  }
  finish { Shine } })
Ball(5, 3, texture {
  pigment { triangular color Red, color Orange, color Yellow, color Green, color Blue, color Violet scale 0.12 rotate x*90 }
  finish { Shine } })

// ---------------------------------------------------------------
// Bottom row: mapping warps and more normals on other shapes
// ---------------------------------------------------------------
// torus with a checker wrapped around it by the toroidal warp
torus {
  0.6, 0.22
  pigment { checker color rgb <0.1, 0.3, 0.6>, color rgb <0.95, 0.95, 0.9> scale <0.0625, 0.125, 1> warp { toroidal orientation y dist_exp 0 major_radius 0.6 } }
  finish { Shine }
  rotate x*-60
  translate <-3.2, -2.6, -0.5>
}

// box with the square pattern folded over its faces by the cubic warp
box {
  -0.5, 0.5
  pigment { square color Red, color Yellow, color Blue, color White scale 0.1 warp { cubic } }
  finish { Shine }
  rotate <30, 40, 0>
  translate <-1.3, -2.6, -0.5>
}

// wood grain seen through a planar warp on a box
box {
  <-0.6, -0.35, -0.35>, <0.6, 0.35, 0.35>
  pigment { wood color_map { M_Wood7A } turbulence 0.05 scale 0.1 warp { planar z, 0 } }
  finish { Shine }
  rotate <20, -25, 0>
  translate <0.5, -2.6, -0.5>
}

// faceted and waves-bumped cylinders, bump_size on a disc
cylinder {
  <0, -0.4, 0>, <0, 0.4, 0>, 0.4
  texture { T_Chrome_2C normal { facets size 0.3 } }
  translate <2.0, -2.6, -0.5>
}
cylinder {
  <0, -0.4, 0>, <0, 0.4, 0>, 0.35
  pigment { waves Cmap3(rgb <0.2, 0.5, 0.4>, rgb <0.8, 1, 0.9>, rgb <0.2, 0.5, 0.4>) scale 0.2 }
  normal { wrinkles bump_size 0.9 scale 0.1 }
  finish { Shine }
  translate <3.3, -2.6, -0.5>
}
disc {
  <0, 0, 0>, <0, 1, -0.3>, 0.8
  pigment { wrinkles color_map { [0 color rgb <0.3, 0.2, 0.1>] [1 color rgb <0.9, 0.7, 0.4>] } scale 0.2 }
  normal { bumps bump_size 0.7 scale 0.08 }
  finish { Shine }
  translate <0, -3.3, -3.2>
}
