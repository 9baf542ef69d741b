// LENIENCY legacy_image_map_orientation: image_map { <vector> png "file" }: a leading orientation vector (pre-3.0) is parsed and ignored
// POV-Ray 3.7: Warning "Old style orientation vector or map type not supported. Ignoring value.". Effect: plane textured with bumpmap_.png
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
plane { z, 1 pigment { image_map { <1,-1,0> png "bumpmap_.png" } scale 2 translate <-1,-1,0> } }
