// LENIENCY legacy_bump_size: bump_size (old amount keyword) in normal { } and inside bump_map { } is silently accepted as the normal amount
// POV-Ray 3.7: no warning. Effect: two bumpy white spheres
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { -x, 0.9 pigment { rgb 1 } normal { bumps bump_size 2 scale 0.1 } }
sphere {  x, 0.9 pigment { rgb 1 } normal { bump_map { png "bumpmap_.png" bump_size 3 } } }
