// s10_lobby.pov - a hotel lobby: a logo decal (once, map_type 0) on a wall, a glowing
// HDR light panel (image_pattern), a rug with a palette bump_map (use_index), PNGs
// with gAMA/sRGB chunks and gamma overrides, an RGBA sign (use_alpha style), a 16-bit
// greyscale image_map, and a cylinder column with a spherical map on a sphere lamp.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.8, -6> look_at <0, 1.4, 0> angle 65 }
light_source { <-2, 4.5, -4> rgb 0.9 }
light_source { <3, 3, -5> rgb 0.3 }

plane { y, 0 pigment { rgb <0.55, 0.5, 0.45> } finish { specular 0.2 } }
plane { -z, -2 pigment { rgb <0.85, 0.8, 0.7> } }

// wall decals: the same picture with different gamma handling, each `once` on the wall
#macro Decal(Pig, X)
  box { <0, 0, 0>, <1, 1, 0.01> texture { pigment { Pig } finish { ambient 0.2 } } scale <1.2, 0.8, 1> translate <X, 2.2, 1.98> }
#end
Decal(pigment { image_map { png "img/pic_gama.png" once map_type 0 } }, -3.4)
Decal(pigment { image_map { png "img/pic_gama10.png" once } }, -2.0)
Decal(pigment { image_map { png "img/pic_srgbchunk.png" gamma 1.0 once } }, -0.6)
Decal(pigment { image_map { png "img/pic.png" gamma srgb once } }, 0.8)
Decal(pigment { image_map { png "img/hills16.png" interpolate 2 } }, 2.2)

// an RGBA sign over a stripe wall: alpha shows the wall through
box { <0, 0, 0>, <1, 1, 0.01>
  texture { pigment { gradient x color_map { [0 rgb <0.2, 0.2, 0.6>] [0.5 rgb <0.2, 0.2, 0.6>] [0.5 rgb <0.8, 0.8, 0.2>] [1 rgb <0.8, 0.8, 0.2>] } scale 0.2 } }
  texture { pigment { image_map { png "img/pic_rgba.png" } } finish { ambient 0.3 } }
  scale <1.8, 1.2, 1> translate <-3.5, 0.6, 1.9> }

// a light panel: image_pattern of an HDR ramp with a colour map, emissive
box { <0, 0, 0>, <1, 1, 0.01>
  texture { pigment { image_pattern { hdr "img/ramp.hdr" interpolate 2 } color_map { [0 rgb <0.1, 0, 0.2>] [0.5 rgb <1, 0.5, 0.1>] [1 rgb <1, 1, 0.8>] } }
            finish { ambient 1 diffuse 0 } }
  scale <1.6, 0.6, 1> translate <1.5, 0.8, 1.9> }

// a rug with a palette GIF bump map using the index, on a pigment from a PPM
box { <-1.2, 0, -1>, <1.2, 0.02, 1>
  texture {
    pigment { image_map { ppm "img/pic.ppm" interpolate 2 } rotate 90*x scale 2 translate <-1, 0, -1> }
    normal { bump_map { gif "img/rings.gif" use_index bump_size 3 } rotate 90*x scale 0.8 }
  }
  translate <0.2, 0, -1.5> }
// a globe lamp with a spherical EXR map and a column with a cylindrical TIFF
sphere { 0, 0.45 pigment { image_map { exr "img/ball.exr" map_type 1 interpolate 2 } } finish { ambient 0.4 } translate <-1.3, 0.45, -0.2> }
cylinder { <0, 0, 0>, <0, 1, 0>, 0.3 pigment { image_map { tiff "img/pic.tif" map_type 2 interpolate 2 } } scale <1, 2.2, 1> translate <1.6, 0, -0.5> }
// a doughnut-shaped ottoman with a torus map of a BMP with transmit all
torus { 0.5, 0.2 pigment { image_map { bmp "img/pic.bmp" map_type 5 transmit all 0.3 } } rotate -20*x translate <3.1, 0.3, -1.2> }
