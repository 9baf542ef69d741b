// s7_valley.pov - a mountain valley: a height field textured by slope and altitude,
// a snow line by slope { point_at }, a lake with aoi-driven fresnel colour, rocks with
// slope normals and a slope-mapped pigment on a torus and a box.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }
camera { location <0, 3.4, -7.5> look_at <0, 0.6, 0> angle 58 }
light_source { <-8, 10, -4> rgb <1, 0.97, 0.9> }
light_source { <6, 4, -8> rgb 0.25 shadowless }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.75, 0.85, 1>] [0.5 rgb <0.3, 0.5, 0.9>] } } }

#declare Rock = texture { pigment { granite color_map { [0 rgb <0.45, 0.42, 0.4>] [1 rgb <0.3, 0.28, 0.25>] } scale 0.3 } normal { granite 0.2 scale 0.3 } }
#declare Grass = texture { pigment { rgb <0.25, 0.5, 0.15> } normal { bumps 0.2 scale 0.05 } }
#declare Snow = texture { pigment { rgb 0.97 } finish { specular 0.3 } }

height_field { png "img/hills16.png" smooth
  texture {
    slope { <0, 1, 0>, 0.6, 1.0 altitude <0, 1, 0>, 0.1, 0.9 }
    texture_map {
      [0.00 Rock]
      [0.45 Rock]
      [0.55 Grass]
      [0.80 Grass]
      [0.85 Snow]
      [1.00 Snow]
    }
  }
  translate <-0.5, 0, -0.5> scale <7, 1.6, 5> translate <0, 0, 2> }

// lake: water whose colour goes with the angle of incidence
plane { y, 0.35
  texture {
    pigment { aoi color_map { [0 rgb <0.05, 0.2, 0.3>] [0.7 rgb <0.15, 0.35, 0.5>] [1 rgb <0.7, 0.8, 0.9>] } }
    finish { reflection { 0.1, 0.6 } specular 0.6 roughness 0.005 }
  } }

// boulders with slope-driven moss (slope y with a wave and turbulence)
#declare Boulder = sphere { 0, 0.35 scale <1.2, 0.8, 1>
  texture {
    slope y
    turbulence 0.1
    texture_map { [0.5 Rock] [0.8 pigment { rgb <0.2, 0.45, 0.1> }] }
  } }
object { Boulder translate <-1.6, 0.4, -2.2> }
object { Boulder rotate 40*y scale 0.8 translate <-0.9, 0.38, -2.8> }
object { Boulder rotate -20*z translate <1.3, 0.4, -2.5> }
// a signpost: a box whose faces get colour by slope in a pigment, point_at a lamp
box { <-0.3, 0, -0.05>, <0.3, 0.4, 0.05>
  pigment { slope { point_at <3, 3, -5> } color_map { [0 rgb <0.3, 0.15, 0.05>] [1 rgb <1, 0.8, 0.5>] } }
  rotate -15*y translate <0.2, 0.9, -3.2> }
// a life ring with aoi shading on the lake
torus { 0.35, 0.1
  pigment { slope { <0, 1, 0> altitude <0, 0, 1>, -0.5, 0.5 } color_map { [0 rgb <1, 0.1, 0.1>] [0.5 rgb 1] [1 rgb <1, 0.1, 0.1>] } frequency 2 }
  translate <2.3, 0.4, -1.5> }
// a glass float whose normal uses slope
sphere { <0.4, 0.5, -1.8>, 0.25
  pigment { rgbf <0.8, 1, 0.9, 0.7> }
  normal { slope { <0, 1, 0>, 0, 1 } 0.5 }
  interior { ior 1.33 } finish { specular 0.8 reflection 0.1 } }
