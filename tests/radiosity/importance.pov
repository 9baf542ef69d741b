// The room with a default importance (#default { radiosity { importance } }) that one
// object overrides: of a sample's rays, those meeting another object or the sky stop early.
#version 3.7;
global_settings { assumed_gamma 1.0 radiosity { } }
#default { radiosity { importance 0.3 } }
camera { location <0, 1.5, -4.5> look_at <0, 1.2, 0> angle 60 }
light_source { <0, 2.6, -0.5> rgb 1 }
#declare White = texture { pigment { rgb 0.8 } finish { diffuse 0.8 ambient 0.4 } }
plane { y, 0 texture { White } }
plane { y, 3 texture { White } }
plane { z, 1.5 texture { White } }
plane { z, -5 texture { White } }
plane { x, -1.6 texture { pigment { rgb <0.8, 0.15, 0.1> } finish { diffuse 0.8 } } }
plane { x, 1.6 texture { pigment { rgb <0.1, 0.6, 0.15> } finish { diffuse 0.8 } } }
sphere { <-0.5, 0.5, 0.2>, 0.5 texture { White } radiosity { importance 1 } }
box { <0.2, 0, -0.6>, <1.0, 1.1, 0.3> rotate y*20 texture { White } }
