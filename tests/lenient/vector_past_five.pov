// LENIENCY vector_past_five: a vector of more than five components written without commas
// past the fifth: each further component takes the fifth's place (Parse_Num_Factor reads five,
// the rest overwrite the last), <1 2 3 4 5 6> is <1, 2, 3, 4, 6>; read by the grammar and by
// the plain-number fast path alike
// POV-Ray 3.7: no warning. Effect: three spheres, sizes and colours from the vectors' fifth components
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-6> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare A = <0 0 0 0 0.2 0.9>;
#declare B = <0, 0, 0, 0, 0.1 0.3 0.6>;
#declare N = 0.5;
#declare C = <N, N, N, N N*0.2 N>;
sphere { <-2, 0, 0> A.transmit pigment { rgb <1, A.transmit, 0> } }
sphere { <0, 0, 0> B.transmit pigment { rgb <0, B.transmit, 1> } }
sphere { <2, 0, 0> C.transmit pigment { rgb <C.transmit, 1, 0> } }
