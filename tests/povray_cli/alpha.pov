// +UA: the default background is transparent; a transmit sphere lets it through by half,
// a filter box by its filter colour; an opaque sphere covers it. The reference
// alpha.povray.png is POV-Ray 3.7's render: povray +Ialpha.pov +Oalpha.povray.png +W64 +H48 -A +UA -D
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -5> look_at 0 }
light_source { <-5, 5, -5> rgb 1 }
sphere { <-1, 0, 0>, 0.8 pigment { rgb <1, 0.5, 0.25> transmit 0.5 } }
sphere { <1, 0, 0>, 0.8 pigment { rgb <0.2, 0.6, 1> } }
box { <-2, -1.5, 0.5>, <2, -1, 1> pigment { rgbf <0.5, 1, 0.5, 0.7> } }
