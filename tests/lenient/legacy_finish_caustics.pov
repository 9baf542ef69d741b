// LENIENCY legacy_finish_caustics: POV-Ray's old `caustics` in a finish, moved to the object's interior as written (not times 45 as interior { caustics } is; parse.cpp Post_Process, Temp_Caustics)
// POV-Ray 3.7: Parse Warning: Caustics value should be specified in 'interior{...}' statement. Effect: bright spots in the glass spheres' shadows
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -7> look_at <0, 0.6, 0> angle 45 }
light_source { <2, 10, -3> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.6 scale 0.5 } }
sphere { <-1.2, 1, 0>, 1 pigment { rgbf <0.9, 0.95, 1, 0.9> } finish { caustics 20 } }
sphere { <1.2, 1, 0>, 1 pigment { rgbf <0.9, 0.95, 1, 0.9> } finish { caustics 20 } interior { ior 1.2 } }
