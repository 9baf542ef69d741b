// finish { ior 1.5 }: POV-Ray 3.7 keeps it and moves it to the object's interior (a plain
// texture's finish only), warning "Index of refraction value should be specified in
// 'interior{...}' statement."; the same picture as interior { ior 1.5 }. A finish's ior
// overrides the interior's.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -6> look_at 0 }
light_source { <-5, 5, -5> color rgb 1 }
background { rgb 0.2 }
sphere { <-1.6, 0, 0>, 1.2 pigment { rgbf <1, 1, 1, 0.95> } finish { ior 1.5 } }
sphere { <1.6, 0, 0>, 1.2 pigment { rgbf <1, 0.9, 0.9, 0.95> } finish { ior 1.2 } interior { ior 2 } }
plane { z, 3 pigment { checker rgb 1 rgb 0 scale 0.5 } }
