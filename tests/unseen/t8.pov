// s8_uvshop.pov - a toy shop shelf: labels and decals placed by uv coordinates on
// balls, crates, rings, a poster mesh and a mesh2 pyramid; uv bump maps and uv tilings.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.4, -6.2> look_at <0, 1.0, 0> angle 60 }
light_source { <-4, 7, -6> rgb 1 }
light_source { <5, 3, -5> rgb 0.35 }

// a floor carpet: uv-mapped plane with a tiling
plane { y, 0 texture { uv_mapping pigment { tiling 5 color_map { [0 rgb <0.4, 0.1, 0.1>] [1 rgb <0.9, 0.7, 0.4>] } scale 0.4 } } }
plane { z, 2 pigment { rgb <0.8, 0.85, 0.9> } }

// a beach ball: uv image map on a sphere, with a uv bump map
sphere { 0, 0.6
  texture {
    pigment { uv_mapping image_map { png "img/pic.png" interpolate 2 } }
    normal { uv_mapping bump_map { png "img/bump.png" bump_size 2 } }
    finish { phong 0.6 }
  }
  rotate <20, -30, 0> translate <-2.5, 0.6, -0.5> }
// a crate: image on the unfolded cube, uv_mapping as an object modifier
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5>
  uv_mapping
  texture { pigment { image_map { tga "img/pic.tga" } } finish { specular 0.2 } }
  rotate 25*y translate <-0.9, 0, 0.3> }
// a ring toy: uv texture_map around a torus
torus { 0.5, 0.18
  texture { uv_mapping
    gradient x
    texture_map {
      [0.5 pigment { rgb <1, 0.2, 0.2> } finish { phong 0.8 }]
      [0.5 pigment { rgb <1, 1, 0.3> } finish { phong 0.2 }]
    }
    scale 0.125 }
  rotate -60*x translate <0.7, 0.7, -0.6> }
// a poster: a mesh of two triangles with uv_vectors, showing a GIF
mesh {
  triangle { <-1, 0, 0>, <1, 0, 0>, <1, 1.4, 0> uv_vectors <0, 0>, <1, 0>, <1, 1> }
  triangle { <-1, 0, 0>, <1, 1.4, 0>, <-1, 1.4, 0> uv_vectors <0, 0>, <1, 1>, <0, 1> }
  texture { uv_mapping pigment { image_map { gif "img/rings.gif" } } finish { ambient 0.3 } }
  translate <1.9, 0.8, 1.9> }
// a smooth-triangle flag with uv_vectors and a uv normal
mesh {
  smooth_triangle { <0, 0, 0>, <-0.3, 0, -1>, <1, 0, 0>, <0.3, 0, -1>, <1, 0.7, 0>, <0.3, 0, -1> uv_vectors <0, 0>, <1, 0>, <1, 1> }
  smooth_triangle { <0, 0, 0>, <-0.3, 0, -1>, <1, 0.7, 0>, <0.3, 0, -1>, <0, 0.7, 0>, <-0.3, 0, -1> uv_vectors <0, 0>, <1, 1>, <0, 1> }
  uv_mapping
  pigment { checker rgb <0.1, 0.3, 0.9> rgb 1 scale 0.25 }
  normal { uv_mapping waves 0.5 frequency 3 }
  translate <-2.4, 1.6, 1.2> }
// a pyramid: mesh2 with uv_vectors, uv_indices and normal_vectors, with a JPEG label
mesh2 {
  vertex_vectors { 5, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1>, <0, 1.3, 0> }
  uv_vectors { 4, <0, 0>, <1, 0>, <0.5, 1>, <0, 1> }
  face_indices { 4, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4> }
  uv_indices { 4, <0, 1, 2>, <0, 1, 2>, <0, 1, 2>, <0, 1, 2> }
  texture { uv_mapping pigment { image_map { jpeg "img/pic444.jpg" } } }
  scale 0.5 rotate 30*y translate <2.2, 0, -1.3> }
// a cushion: mesh2 with one uv per vertex and per-vertex normals
mesh2 {
  vertex_vectors { 4, <-0.6, 0, -0.4>, <0.6, 0, -0.4>, <0.6, 0, 0.4>, <-0.6, 0, 0.4> }
  normal_vectors { 4, <-0.3, 1, -0.3>, <0.3, 1, -0.3>, <0.3, 1, 0.3>, <-0.3, 1, 0.3> }
  uv_vectors { 4, <0, 0>, <2, 0>, <2, 2>, <0, 2> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  uv_mapping
  texture { pigment { tiling 12 color_map { [0 rgb <0.2, 0.6, 0.3>] [1 rgb <0.95, 0.95, 0.7>] } scale 0.25 } finish { specular 0.4 } }
  translate <-0.3, 0.05, -2.1> }
