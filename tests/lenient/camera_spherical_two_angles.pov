// LENIENCY camera_spherical_two_angles: camera angle takes a second float only for the spherical camera (H_Angle, optional V_Angle); for perspective "angle 60 180" is an error
// POV-Ray 3.7: no warning. Effect: small red sphere seen through a spherical camera
#version 3.7;
global_settings { assumed_gamma 1 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
camera { spherical location <0,0,-4> look_at 0 angle 90 45 }
sphere { 0, 1 pigment { rgb <1,0,0> } }
