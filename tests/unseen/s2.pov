// s2: a table setting of lathe and sor objects (vase, goblets, bowl, candlestick) on a wooden table
#version 3.7;
#include "colors.inc"
#include "textures.inc"
#include "woods.inc"
#include "metals.inc"
#include "glass.inc"

global_settings { assumed_gamma 1.0 max_trace_level 20 }

camera {
  perspective
  location <0, 4.2, -8.5>
  look_at <0, 1.3, 0>
  angle 48
}

light_source { <-5, 9, -6> color rgb <1, 0.95, 0.88>
  area_light <1.5, 0, 0>, <0, 0, 1.5>, 3, 3 adaptive 1 }
light_source { <6, 5, -7> color rgb 0.3 shadowless }

background { color rgb <0.15, 0.15, 0.2> }

// back wall
plane { z, 5
  pigment { gradient y color_map { [0 color rgb <0.55, 0.45, 0.35>] [1 color rgb <0.3, 0.25, 0.2>] } scale 6 }
  finish { diffuse 0.8 }
}

// floor
plane { y, -3 pigment { color rgb <0.3, 0.22, 0.15> } }

// table top: a wooden box
box { <-5, -0.3, -3>, <5, 0, 4>
  texture { T_Wood10 scale 0.6 rotate <0, 90, 0> }
}

// Vase: lathe with cubic_spline (first and last points are control points)
lathe {
  cubic_spline
  9,
  <0.0, -0.2>, <0.6, 0.0>, <0.9, 0.5>, <0.7, 1.3>, <0.35, 2.0>, <0.3, 2.4>, <0.5, 2.8>, <0.55, 2.9>, <0.6, 3.1>
  texture { pigment { color rgb <0.15, 0.35, 0.7> } finish { specular 0.7 roughness 0.01 reflection 0.2 } }
  translate <-2.2, 0, 1.5>
}

// Goblet: sor object (closed)
#declare Goblet = sor {
  10,
  <0.0, -0.1>, <0.5, 0.0>, <0.42, 0.08>, <0.12, 0.3>, <0.1, 0.6>, <0.12, 0.85>, <0.35, 1.05>, <0.5, 1.4>, <0.55, 1.9>, <0.55, 2.0>

}

object { Goblet
  material {
    texture { pigment { Col_Glass_Bluish } finish { specular 0.7 roughness 0.001 reflection 0.1 } }
    interior { ior 1.5 }
  }
  translate <1.3, 0, -1.2>
}
object { Goblet
  texture { T_Silver_3C }
  scale 0.85
  translate <2.3, 0, 0.9>
}

// Open sor: a napkin ring / tube with no caps
sor {
  5,
  <0.30, -0.1>, <0.35, 0.0>, <0.28, 0.25>, <0.35, 0.5>, <0.30, 0.6>
  open
  texture { T_Copper_3C }
  rotate <0, 0, 90>
  translate <-0.6, 0.35, -2.0>
}

// Bowl: lathe with quadratic_spline (first point is a control point)
lathe {
  quadratic_spline
  7,
  <0.0, 0.0>, <0.0, 0.02>, <0.6, 0.05>, <1.1, 0.35>, <1.3, 0.8>, <1.25, 0.82>, <1.0, 0.4>
  texture { T_Brass_3C }
  translate <-0.1, 0, 1.2>
}

// fruit in the bowl
sphere { <-0.35, 0.4, 1.1>, 0.3 pigment { color rgb <0.85, 0.15, 0.05> } finish { phong 0.6 } }
sphere { <0.25, 0.4, 1.3>, 0.3 pigment { color rgb <0.95, 0.65, 0.05> } finish { phong 0.6 } }
sphere { <-0.05, 0.55, 1.55>, 0.28 pigment { color rgb <0.3, 0.7, 0.1> } finish { phong 0.6 } }

// Candlestick: lathe with linear_spline
lathe {
  linear_spline
  10,
  <0.0, 0.0>, <0.6, 0.0>, <0.6, 0.1>, <0.3, 0.2>, <0.15, 0.4>, <0.12, 1.6>, <0.3, 1.7>, <0.28, 1.8>, <0.1, 1.8>, <0.0, 1.8>
  texture { T_Gold_2C }
  translate <2.8, 0, 2.2>
}
// candle
cylinder { <2.8, 1.75, 2.2>, <2.8, 2.9, 2.2>, 0.09 pigment { color rgb <0.95, 0.93, 0.85> } }

// Small cup: lathe with bezier_spline (4 points per segment)
lathe {
  bezier_spline
  8,
  <0.0, 0.0>, <0.3, 0.0>, <0.5, 0.0>, <0.5, 0.1>,
  <0.5, 0.1>, <0.45, 0.4>, <0.55, 0.7>, <0.6, 0.8>
  texture { pigment { color rgb <0.9, 0.9, 0.85> } finish { specular 0.5 roughness 0.02 reflection 0.05 } }
  translate <-2.6, 0, -1.2>
}

// Plate: flat cylinder under the cup
cylinder { <-2.6, 0, -1.2>, <-2.6, 0.04, -1.2>, 0.9
  pigment { color rgb <0.95, 0.95, 0.95> } finish { specular 0.4 reflection 0.1 }
}
