// s5_room.pov - an evening room: a table lamp (light in a union, looks_like bulb,
// double-illuminated shade), a mirror, a vampire that the mirror ignores, a ghost seen
// only in the mirror, a glass vase, a light group for a display cabinet, and a
// projector shining through a slide.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <1.5, 2.2, -5.5> look_at <-0.2, 1.1, 0.5> angle 62 }

light_source { <4, 6, -6> rgb 0.35 }

// room
plane { y, 0 pigment { wood color_map { [0 rgb <0.5, 0.3, 0.15>] [1 rgb <0.35, 0.2, 0.1>] } turbulence 0.05 scale 0.3 rotate 90*x } finish { specular 0.3 } }
plane { z, 2.5 pigment { rgb <0.8, 0.75, 0.65> } }
plane { x, -3 pigment { rgb <0.7, 0.75, 0.8> } }

// mirror on the back wall
box { <-2.2, 0.4, 2.4>, <0.3, 2.6, 2.45> pigment { rgb 0.1 } finish { ambient 0 diffuse 0.05 reflection 0.9 } }
box { <-2.3, 0.3, 2.45>, <0.4, 2.7, 2.48> pigment { rgb <0.4, 0.3, 0.1> } }

// table lamp: a union that carries its light, a bulb drawn by looks_like and a shade
#declare Lamp = union {
  light_source { <0, 1.15, 0> rgb <1, 0.85, 0.6>
    looks_like { sphere { 0, 0.08 pigment { rgb <1, 1, 0.8> } finish { ambient 1 diffuse 0 } } }
    fade_distance 2 fade_power 1 }
  cylinder { <0, 0, 0>, <0, 0.05, 0>, 0.25 pigment { rgb 0.2 } finish { specular 0.6 } }
  cylinder { <0, 0, 0>, <0, 1.0, 0>, 0.03 pigment { rgb 0.2 } finish { specular 0.6 } }
  cone { <0, 0.95, 0>, 0.4, <0, 1.45, 0>, 0.2 open
    pigment { rgbf <1, 0.9, 0.7, 0.3> } finish { diffuse 0.8 ambient 0.1 } double_illuminate }
}
object { Lamp translate <-1.6, 0, 0.8> }

// the vampire (not in the mirror) and the ghost (only in the mirror)
sphere { <-0.6, 0.5, 0.9>, 0.5 pigment { rgb <0.7, 0.1, 0.1> } finish { phong 0.5 } no_reflection }
sphere { <0.6, 0.7, 1.3>, 0.3 pigment { rgbt <0.9, 0.95, 1, 0.4> } no_image }
// a glass vase and a card lit from behind
sphere { <0.9, 0.4, -0.3>, 0.4 pigment { rgbf <0.9, 1, 0.95, 0.9> } finish { specular 0.8 roughness 0.005 reflection { 0.05, 1 fresnel } } interior { ior 1.5 } no_radiosity }
triangle { <1.5, 0, 0.5>, <2.6, 0, 0.7>, <2.0, 1.4, 0.6> pigment { rgb <1, 0.9, 0.7> } double_illuminate }

// a display cabinet: a light group that only lights its figurines
light_group {
  light_source { <2.2, 2.2, 1.6> rgb <0.3, 0.6, 1.2> spotlight point_at <2.2, 0, 1.6> radius 20 falloff 35 }
  box { <1.6, 0.8, 1.2>, <2.8, 0.85, 2.2> pigment { rgb 0.9 } }
  sphere { <1.9, 1.0, 1.6>, 0.15 pigment { rgb 1 } finish { phong 0.8 } }
  cone { <2.4, 0.85, 1.7>, 0.15, <2.4, 1.3, 1.7>, 0 pigment { rgb <1, 0.8, 0.3> } }
  global_lights on
}
// a projector: a light seen only through a slide
#declare Slide = box { <-0.3, -0.2, 0>, <0.3, 0.2, 0.01> }
light_source { <0, 0, 0> rgb <2, 2, 1.6>
  projected_through { object { Slide translate <0, 0, 0.4> } }
  rotate <-5, -20, 0> translate <0.3, 1.4, -3> }
object { Slide pigment { rgbf <0.3, 0.8, 1, 0.8> } rotate <-5, -20, 0> translate <0.3, 1.4, -3> translate <0, 0, 0.4> }
