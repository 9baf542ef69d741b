// LENIENCY directive_inside_object: directives at any token boundary inside objects and vectors: #if/#else/#end between sphere parameters, #declare in the middle of a vector, #include in the middle of a colour vector
// POV-Ray 3.7: no warning. Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { <0, #declare Y = 0; Y, 0>, #if (1) 1 #else 0.2 #end
  pigment { rgb #if (0) <0,0,1> #else #include "lenient_red.inc" #end }
}
