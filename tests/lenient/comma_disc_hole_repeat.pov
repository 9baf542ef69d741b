// LENIENCY comma_disc_hole_repeat: disc hole radius is read in a loop (CASE_FLOAT without EXIT), so extra floats overwrite it: disc {0, -z, 1, 0.8 0.3} has hole 0.3
// POV-Ray 3.7: no warning. Effect: red disc with a small (0.3) hole
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
disc { 0, -z, 1, 0.8 0.3 pigment { rgb <1,0,0> } }
