// LENIENCY array_fractional_index: array sizes and subscripts are truncated: array[2.9] has 2 elements, A[1.7] is A[1]; blank space (not comments) allowed before "["
// POV-Ray 3.7: no warning. Effect: red sphere of radius A[1]=1
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare A = array[2.9] { 0.5, 1 };
sphere { 0, A  [1.7] pigment { rgb <1,0,0> } }
