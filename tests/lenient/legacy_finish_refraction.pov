// refraction F (before POV-Ray 3.0): of a finish or an interior, it multiplies the light
// passing through the surface; a plain texture's finish sets it (1 unless given) over the
// interior's, so an interior's counts only under a pattern of textures. POV-Ray 3.7 warns
// "Refraction value unnecessary to turn on refraction."
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -7> look_at 0 }
light_source { <-5, 5, -5> color rgb 1 }
background { rgb 0.2 }
sphere { <-2.2, 0, 0>, 1 pigment { rgbf <1, 1, 1, 0.95> } finish { refraction 0 } interior { ior 1.0 } }
sphere { <0, 0, 0>, 1 pigment { rgbf <1, 0.8, 0.8, 0.9> } finish { refraction 0.5 ior 1.5 } interior { refraction 0 } }
sphere { <2.2, 0, 0>, 1
  texture { checker texture { pigment { rgbf <1, 1, 1, 0.9> } } texture { pigment { rgbf <0.5, 1, 1, 0.9> } } scale 0.3 }
  interior { ior 1.3 refraction 0.3 } }
plane { z, 3 pigment { checker rgb 1 rgb 0 scale 0.5 } }
