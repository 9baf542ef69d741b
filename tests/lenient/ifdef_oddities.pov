// LENIENCY ifdef_oddities: #ifdef reads its argument with Inside_Ifdef set, so keywords and numbers are just "undefined" (no error); #ifdef(A[i]) tests an array element; #undef A[i] un-sets an element; #undef of an unknown name only warns
// POV-Ray 3.7: Warning "Attempt to undef unknown identifier". Effect: red sphere only
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare A = array[3];
#declare A[1] = 1;
#undef Nothing
#ifdef (A[1])   sphere { 0, 1 pigment { rgb <1,0,0> } } #end
#ifdef (A[2])   sphere { 0, 1.5 pigment { rgb <0,1,0> } } #end
#ifdef (sphere) sphere { 0, 1.5 pigment { rgb <0,0,1> } } #end
#ifdef (1)      sphere { 0, 1.5 pigment { rgb <0,0,1> } } #end
#undef A[1]
#ifdef (A[1])   sphere { 0, 1.5 pigment { rgb <0,1,0> } } #end
