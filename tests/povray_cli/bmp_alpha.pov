// A 32-bit BMP's fourth byte is its alpha, as POV-Ray reads it (a 4×4 image whose columns are
// alpha 0, 1/3, 2/3 and 1 over a green background). bmp_alpha.povray.png is POV-Ray 3.7's
// render: povray +Ibmp_alpha.pov +Obmp_alpha.povray.png +W8 +H8 -A -D
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0.5, 0.5, -2> look_at <0.5, 0.5, 0> right x up y }
background { rgb <0, 1, 0> }
plane { z, 0 pigment { image_map { bmp "a32.bmp" } } finish { ambient 1 diffuse 0 } }
