// s1_gallery.pov - a small picture gallery: one framed picture per image format.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }

camera { location <0, 1.7, -6.5> look_at <0, 1.45, 0> angle 62 right x*image_width/image_height }
light_source { <0, 4.5, -4>, color rgb 0.9 }
light_source { <-5, 3, -6>, color rgb 0.4 shadowless }

// room
plane { y, 0
  texture { pigment { checker rgb <0.55, 0.42, 0.3> rgb <0.42, 0.3, 0.2> scale 0.6 }
            normal { bump_map { png "img/bump.png" bump_size 1.5 interpolate 2 } rotate 90*x scale 0.6 }
            finish { specular 0.3 roughness 0.02 reflection 0.08 } } }
plane { -z, -2.2 pigment { rgb <0.85, 0.82, 0.75> } finish { diffuse 0.8 } }
plane { y, 4 pigment { rgb 0.9 } }

#declare FrameTex = texture { pigment { rgb <0.35, 0.2, 0.08> } finish { specular 0.4 phong_size 40 } }

#macro Picture(Pig, Pos, Sz)
  union {
    box { <-0.06, -0.06, 0.02>, <1.06, 1.06, 0.08> texture { FrameTex } }
    box { <0, 0, 0>, <1, 1, 0.01> texture { pigment { Pig } finish { ambient 0.15 diffuse 0.85 } } }
    scale <Sz*1.5, Sz, 1> translate Pos
  }
#end

// top row: the format from the keyword
Picture(pigment { image_map { png "img/pic.png" } }, <-3.4, 2.5, 2.05>, 0.9)
Picture(pigment { image_map { jpeg "img/pic.jpg" interpolate 2 } }, <-1.9, 2.5, 2.05>, 0.9)
Picture(pigment { image_map { gif "img/rings.gif" } }, <-0.4, 2.5, 2.05>, 0.9)
Picture(pigment { image_map { tga "img/pic" } }, <1.1, 2.5, 2.05>, 0.9)
Picture(pigment { image_map { ppm "img/pic.ppm" gamma 2.2 } }, <2.6, 2.5, 2.05>, 0.9)
// bottom row: the format from the extension
Picture(pigment { image_map { "img/pic.pgm" } }, <-3.4, 1.2, 2.05>, 0.9)
Picture(pigment { image_map { "img/pic.tif" gamma srgb interpolate 4 } }, <-1.9, 1.2, 2.05>, 0.9)
Picture(pigment { image_map { "img/pic.bmp" } }, <-0.4, 1.2, 2.05>, 0.9)
Picture(pigment { image_map { "img/ramp.hdr" interpolate 3 } }, <1.1, 1.2, 2.05>, 0.9)
Picture(pigment { image_map { "img/ball.exr" } }, <2.6, 1.2, 2.05>, 0.9)

// a globe with a spherical map and a vase with a cylindrical one
sphere { 0, 0.55
  pigment { image_map { jpeg "img/pic.jpg" map_type 1 interpolate 2 } rotate -30*y }
  finish { specular 0.5 roughness 0.01 }
  translate <-1.6, 0.55, -1.2> }
cylinder { <0, 0, 0>, <0, 1.1, 0>, 0.35
  pigment { image_map { tga "img/pic.tga" map_type 2 } scale <1, 1.1, 1> }
  translate <0.4, 0, -0.8> }
torus { 0.45, 0.16
  pigment { image_map { png "img/rings_pal.png" map_type 5 interpolate 2 } }
  rotate -70*x translate <2.0, 0.62, -1.0> }
