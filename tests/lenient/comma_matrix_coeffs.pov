// LENIENCY comma_matrix_coeffs: matrix <12 floats> without commas (Parse_Matrix), quadric vectors and poly coefficient list without commas (Parse_Quadric, Parse_Coeffs); a comma or parentheses are needed before negative numbers
// POV-Ray 3.7: no warning. Effect: three red spheres (matrix-shifted sphere, quadric sphere, poly sphere)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { 0 0.5 matrix <1 0 0  0 1 0  0 0 1, -1.5 0 0> pigment { rgb <1,0,0> } }
quadric { <1 1 1> <0 0 0> <0 0 0> (-0.25) pigment { rgb <1,0,0> } }
poly { 2 <1 0 0 0 1 0 0 1 0, -0.25> translate x*1.5 pigment { rgb <1,0,0> } }
