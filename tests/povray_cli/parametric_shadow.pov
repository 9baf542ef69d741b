// A transparent parametric ball casting light on itself and the floor: its search finds the
// nearest crossing only, so a shadow ray searches again from each crossing (POV-Ray's walk).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -5> look_at 0 }
light_source { <3, 10, -3> rgb 1 }
background { rgb 0.2 }
plane { y, -1.2 pigment { rgb 1 } }
parametric { function { cos(u) * sin(v) } function { cos(v) } function { sin(u) * sin(v) }
  <0, 0>, <2 * pi, pi> contained_by { box { -1.1, 1.1 } } accuracy 0.001 max_gradient 2
  interior { ior 1.5 } pigment { rgbf <1, 0.6, 0.6, 0.7> } }
