// s9_vitrine.pov - a museum vitrine: a glass case on a mirrored plinth, exhibits that
// hide from the camera or from mirrors, a lamp whose bulb is seen in the mirror, a
// backlit parchment (double_illuminate) and uv-mapped exhibits.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }
camera { location <1.2, 2.3, -5> look_at <0, 1.1, 0> angle 55 }
light_source { <-3, 6, -5> rgb 0.8 }
light_source { <0, 2.2, 2.2> rgb <1, 0.9, 0.7> fade_distance 2 fade_power 2
  looks_like { sphere { 0, 0.1 pigment { rgb <1, 1, 0.8> } finish { ambient 1 diffuse 0 } } } }

plane { y, 0 pigment { checker rgb 0.7 rgb 0.2 scale 0.7 } finish { reflection 0.15 } }
// mirror wall behind the case
box { <-3, 0, 2.8>, <3, 3.5, 2.9> pigment { rgb 0.05 } finish { reflection 0.92 ambient 0 diffuse 0.05 } }
// plinth
box { <-1.5, 0, -1>, <1.5, 0.6, 1> pigment { rgb <0.3, 0.25, 0.2> } finish { specular 0.3 } }
// glass case (five thin panes), visible in image and in mirror
#declare Pane = texture { pigment { rgbf <0.95, 1, 0.97, 0.92> } finish { specular 0.6 roughness 0.005 reflection { 0.02, 0.3 fresnel } ambient 0 diffuse 0.05 } }
union {
  box { <-1.4, 0.601, -0.92>, <1.4, 2.0, -0.9> }
  box { <-1.4, 0.601, 0.9>, <1.4, 2.0, 0.92> }
  box { <-1.42, 0.601, -0.88>, <-1.405, 2.0, 0.88> }
  box { <1.405, 0.601, -0.88>, <1.42, 2.0, 0.88> }
  box { <-1.42, 2.01, -0.92>, <1.42, 2.03, 0.92> }
  texture { Pane } interior { ior 1.5 } }

// exhibit 1: a golden orb seen directly but not in the mirror
sphere { <-0.8, 0.95, 0>, 0.35 pigment { rgb <1, 0.75, 0.3> } finish { metallic reflection 0.3 specular 0.8 } no_reflection }
// exhibit 2: a ghost vase: only in the mirror (and through the glass it is hidden)
cone { <0, 0.6, 0.2>, 0.25, <0, 1.4, 0.2>, 0.1 pigment { rgb <0.3, 0.8, 1> } no_image }
// exhibit 3: a uv-mapped globe with the picture
sphere { 0, 0.3 texture { uv_mapping pigment { image_map { png "img/pic.png" interpolate 2 } } finish { phong 0.5 } } rotate 70*y translate <0.75, 0.9, -0.1> }
// a parchment hung in the case, lit from behind by the lamp
box { <-0.5, 0, 0>, <0.5, 0.7, 0.005> pigment { image_map { bmp "img/pic.bmp" once } scale <1, 0.7, 1> translate <-0.5, 0, 0> } double_illuminate
  translate <0.2, 1.15, 0.7> }
// a hidden shadow-caster above the case: only its shadow falls on the case top
disc { <0, 3, 0>, y, 0.4 pigment { rgb 1 } no_image no_reflection translate <-0.4, 0.5, -0.6> }
// a transparent label, through which the orb is seen; the label itself is no_reflection
box { <-0.3, 0.62, -1.1>, <0.3, 0.8, -1.05> pigment { rgbt <1, 1, 0.9, 0.6> } no_reflection no_radiosity }
