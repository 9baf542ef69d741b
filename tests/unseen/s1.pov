// s1: TrueType text objects in four POV-Ray fonts (one glass), with prisms on a checkered floor
#version 3.7;
#include "colors.inc"
#include "textures.inc"
#include "metals.inc"
#include "glass.inc"

global_settings { assumed_gamma 1.0 max_trace_level 10 }

camera {
  perspective
  location <0, 2.6, -8>
  look_at <0, 0.8, -0.3>
  angle 55
}

light_source { <-6, 10, -8> color rgb <1, 0.97, 0.9> }
light_source { <7, 6, -5> color rgb 0.35 shadowless }
light_source {
  <2, 8, -3> color rgb 0.4
  area_light <2, 0, 0>, <0, 0, 2>, 3, 3
  adaptive 1
}

background { color rgb <0.55, 0.65, 0.85> }

// checkered floor
plane { y, 0
  pigment { checker color rgb <0.85, 0.85, 0.8> color rgb <0.25, 0.3, 0.4> scale 1.0 }
  finish { diffuse 0.8 reflection 0.12 }
}

// back wall with a soft gradient
plane { z, 6
  pigment { gradient y color_map { [0 color rgb <0.9, 0.85, 0.75>] [1 color rgb <0.5, 0.6, 0.8>] } scale 8 }
  finish { diffuse 0.7 }
}

// Title: Times Roman, thick, standing upright, centered
text { ttf "timrom.ttf" "POV-Ray" 0.5, 0
  pigment { color rgb <0.8, 0.1, 0.1> }
  finish { specular 0.6 roughness 0.02 reflection 0.1 }
  scale 1.3
  translate <-2.9, 1.9, 1.5>
}

// Cyrvetic with a 2-D offset vector (stair-stepped letters), rotated
text { ttf "cyrvetic.ttf" "Scene" 0.3, <0.1, -0.05>
  pigment { color rgb <0.1, 0.6, 0.25> }
  finish { specular 0.5 roughness 0.01 reflection 0.15 }
  scale 1.0
  rotate <0, -20, 0>
  translate <-3.7, 0.0, 0.6>
}

// Crystal font with a glass material, lying slightly tilted
text { ttf "crystal.ttf" "Glass" 0.4, 0
  material {
    texture { pigment { rgbf <0.85, 1, 0.9, 0.9> } finish { specular 0.8 roughness 0.005 reflection 0.1 } }
    interior { ior 1.5 }
  }
  scale <1.1, 1.1, 1>
  rotate <0, 8, 0>
  translate <-1.2, 0.0, -1.8>
}

// POV logo font, gold, scaled and rotated
text { ttf "povlogo.ttf" "P" 0.25, 0
  texture { T_Gold_3C }
  scale 1.4
  rotate <0, -15, 0>
  translate <2.45, 0.42, 0.6>
}

// A thin, flat line of text using a scalar offset, lying on the floor
text { ttf "timrom.ttf" "3.7" 0.05, 0.05
  pigment { color rgb <0.1, 0.3, 0.8> }
  finish { phong 0.5 }
  rotate <90, -10, 0>
  scale 0.9
  translate <1.2, 0.01, -3.5>
}

// Hexagonal prism pedestal (linear)
prism {
  linear_sweep
  linear_spline
  0, 0.6, 7,
  <1, 0>, <0.5, 0.866>, <-0.5, 0.866>, <-1, 0>, <-0.5, -0.866>, <0.5, -0.866>, <1, 0>
  texture { pigment { marble turbulence 0.8 color_map { [0 color rgb <0.95,0.95,0.9>] [0.7 color rgb <0.7,0.7,0.75>] [1 color rgb <0.3,0.3,0.35>] } scale 0.5 }
            finish { specular 0.4 reflection 0.08 } }
  scale <1.0, 0.7, 1.0>
  translate <2.9, 0, 0.7>
}

// Star-shaped prism, quadratic spline
prism {
  linear_sweep
  quadratic_spline
  0, 0.4, 11,
  <0.3, -0.3>, <1.0, 0.0>, <0.3, 0.3>, <0.0, 1.0>, <-0.3, 0.3>, <-1.0, 0.0>,
  <-0.3, -0.3>, <0.0, -1.0>, <0.3, -0.3>, <1.0, 0.0>, <0.3, 0.3>
  pigment { color rgb <1.0, 0.75, 0.1> }
  finish { phong 0.7 metallic }
  scale 0.8
  rotate <0, 30, 0>
  translate <-2.4, 0, -2.4>
}
