// s2_terrain.pov - height fields from several image formats, decal images with once,
// stained glass from palette images with filter/transmit per entry.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0.5, 3.6, -8> look_at <0.5, 0.8, 0.5> angle 62 }
light_source { <-4, 9, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.3 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.7, 0.8, 1>] [1 rgb <0.2, 0.35, 0.8>] } } }

plane { y, -0.01 pigment { rgb <0.35, 0.45, 0.3> } }

#declare Terrain = texture {
  pigment { gradient y color_map { [0 rgb <0.2, 0.4, 0.15>] [0.6 rgb <0.5, 0.4, 0.3>] [0.85 rgb 1] } translate -0.01*y }
  finish { diffuse 0.8 } }

// 16-bit PNG, smooth
height_field { png "img/hills16.png" smooth texture { Terrain } translate <-0.5, 0, -0.5> scale <2.2, 0.9, 1.6> translate <-2.6, 0, 0.6> }
// 16-bit PGM, extension-inferred, water_level
height_field { "img/hills16.pgm" water_level 0.2 texture { Terrain } translate <-0.5, 0, -0.5> scale <2.2, 0.9, 1.6> translate <0, 0, 0.6> }
// palette GIF: heights are palette indices
height_field { gif "img/mound.gif" smooth texture { Terrain } translate <-0.5, 0, -0.5> scale <2.2, 0.9, 1.6> translate <2.6, 0, 0.6> }
// 8-bit PGM and colour formats: TGA, BMP, JPEG
height_field { pgm "img/pic.pgm" texture { Terrain } translate <-0.5, 0, -0.5> scale <1.5, 0.3, 1> translate <-3, 0, -1.8> }
height_field { tga "img/pic.tga" texture { Terrain } translate <-0.5, 0, -0.5> scale <1.5, 0.3, 1> translate <-1.2, 0, -1.8> }
height_field { bmp "img/pic.bmp" texture { Terrain } translate <-0.5, 0, -0.5> scale <1.5, 0.3, 1> translate <0.6, 0, -1.8> }
height_field { "img/pic.jpg" smooth texture { Terrain } translate <-0.5, 0, -0.5> scale <1.5, 0.3, 1> translate <2.4, 0, -1.8> }

// stained-glass panes from palette images
box { <0, 0, 0>, <1, 1, 0.02>
  pigment { image_map { gif "img/rings.gif" filter 0, 0.9 filter 5, 0.6 transmit 2, 0.7 } }
  finish { ambient 0.3 diffuse 0.6 }
  scale 1.6 translate <-2.5, 1.2, 2.6> }
box { <0, 0, 0>, <1, 1, 0.02>
  pigment { image_map { png "img/rings_pal.png" transmit all 0.4 } }
  finish { ambient 0.3 diffuse 0.6 }
  scale 1.6 translate <-0.8, 1.2, 2.6> }
box { <0, 0, 0>, <1, 1, 0.02>
  pigment { image_map { png "img/pic.png" filter all 0.7 interpolate 2 } }
  finish { ambient 0.3 diffuse 0.6 }
  scale 1.6 translate <0.9, 1.2, 2.6> }
// a decal: the image once, in the middle of a brick wall; image_pattern for the rest
box { <-1, 0, 0>, <1, 2, 0.3>
  texture { pigment { brick rgb 0.8 rgb <0.6, 0.2, 0.1> brick_size <0.3, 0.1, 0.3> mortar 0.02 } }
  texture { pigment { image_map { png "img/pic_rgba.png" once } scale 0.8 translate <-0.4, 0.6, 0> } }
  translate <3.6, 0, 3> }
sphere { <3.6, 0.5, -0.2>, 0.5
  pigment { image_pattern { jpeg "img/bump.jpg" interpolate 2 } color_map { [0 rgb <0.1, 0.1, 0.5>] [1 rgb <1, 0.8, 0.2>] } scale 0.5 } }
