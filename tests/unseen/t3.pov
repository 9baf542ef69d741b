// s3_tiles.pov - a bathroom corner: tiled floor and walls with tiling/pavement patterns,
// a fractal mosaic, tiling normals, texture_maps with turbulence and warps.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
camera { location <2.2, 2.6, -4.2> look_at <-0.3, 0.9, 0.8> angle 60 }
light_source { <3, 5, -4> rgb 0.9 }
light_source { <-1, 3.5, -2> rgb <0.4, 0.4, 0.45> }

// floor: tiling 24 with a tile/grout texture_map
plane { y, 0
  texture {
    tiling 24
    texture_map {
      [0.0 pigment { rgb <0.15, 0.15, 0.17> } finish { diffuse 0.6 }]
      [0.05 pigment { rgb <0.15, 0.15, 0.17> } finish { diffuse 0.6 }]
      [0.06 pigment { granite color_map { [0 rgb <0.9, 0.88, 0.8>] [1 rgb <0.6, 0.55, 0.5>] } scale 0.3 } finish { specular 0.4 reflection 0.05 }]
      [1.0 pigment { rgb <0.75, 0.7, 0.62> } finish { specular 0.4 reflection 0.05 }]
    }
    scale 0.35 rotate 15*y
  } }
// back wall: pavement hexagons with a normal and a colour_map
plane { -z, -1.5
  texture {
    pigment { pavement number_of_sides 6 number_of_tiles 2 pattern 1 form 0 exterior 1
      color_map { [0 rgb <0.2, 0.4, 0.6>] [0.1 rgb <0.3, 0.55, 0.75>] [0.9 rgb <0.85, 0.92, 1>] [1 rgb 1] }
      rotate 90*x scale 0.25 }
    normal { pavement number_of_sides 6 number_of_tiles 2 pattern 1 bump_size 0.5 rotate 90*x scale 0.25 }
    finish { phong 0.6 phong_size 60 }
  } }
// left wall: triangle pavement with warp turbulence
plane { x, -2
  texture {
    pigment { pavement number_of_sides 3 number_of_tiles 4 pattern 2 interior 2 exterior 0 form 2
      warp { turbulence 0.08 octaves 3 }
      color_map { [0 rgb <0.55, 0.2, 0.1>] [0.5 rgb <0.85, 0.6, 0.35>] [1 rgb <1, 0.95, 0.85>] }
      rotate 90*z scale 0.3 }
    finish { diffuse 0.8 }
  } }
// a mosaic panel: mandel with exponent and exterior colouring
box { <-1.2, 0.6, -0.02>, <0.4, 2.0, 0.02>
  texture {
    pigment { mandel 50 exponent 3 exterior 1, 0.02 interior 0, 1
      color_map { [0 rgb <0.05, 0.05, 0.2>] [0.3 rgb <0.8, 0.3, 0.1>] [0.7 rgb <1, 0.9, 0.4>] [1 rgb 1] }
      scale 0.6 translate <-0.4, 1.3, 0> }
    finish { ambient 0.25 }
  }
  translate <0, 0, 1.45> }
// a julia ball and a magnet ball on the floor
sphere { <0.4, 0.45, -0.3>, 0.45
  pigment { julia <-0.745, 0.113>, 60 interior 1, 1 exterior 2, 0.3
    color_map { [0 rgb <0, 0.1, 0.3>] [0.5 rgb <0.2, 0.8, 0.6>] [1 rgb 1] }
    scale 0.5 rotate 20*z }
  finish { phong 0.8 reflection 0.1 } }
sphere { <-0.9, 0.35, -0.8>, 0.35
  pigment { magnet 2 mandel 40 exterior 3, 0.5
    color_map { [0 rgb <0.3, 0, 0.3>] [0.5 rgb <1, 0.5, 0>] [1 rgb <1, 1, 0.7>] }
    scale 0.4 rotate 90*x translate <0.5, 0, 0> }
  finish { phong 0.8 } }
// a box with tiling normals and a tiling texture_map with turbulence
box { <-0.4, 0, -0.4>, <0.4, 0.7, 0.4>
  texture {
    tiling 11
    texture_map {
      [0.3 pigment { rgb <0.9, 0.7, 0.2> } normal { tiling 11 0.6 scale 0.15 } finish { specular 0.5 }]
      [0.7 pigment { rgb <0.2, 0.3, 0.8> } finish { specular 0.5 }]
    }
    turbulence 0.05
    scale 0.15
  }
  rotate 30*y translate <1.5, 0, 0.6> }
// a pillar with tilings 7 and 19 layered
cylinder { <0, 0, 0>, <0, 2.5, 0>, 0.25
  texture { pigment { tiling 7 color_map { [0 rgb <0.1, 0.3, 0.1>] [1 rgb <0.7, 1, 0.6>] } scale 0.08 } }
  texture { pigment { tiling 19 color_map { [0 rgbt <1, 1, 1, 1>] [0.5 rgbt <1, 1, 1, 1>] [1 rgbt <1, 0.2, 0.2, 0.3>] } scale 0.12 rotate 45*y } }
  translate <-1.5, 0, 0.9> }
