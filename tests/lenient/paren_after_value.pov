// LENIENCY paren_after_value: a `(` after a declared value that is not a function starts the next value (`sphere { Centre (R + 0.2) }`): only a function or a spline is called with `(` (Parse_Unknown_Function is reached from an identifier only when it names a function), so a vector or float identifier ends its expression there, here also when a macro's `(...)` result follows one (macros/macro3.pov without its comma)
// POV-Ray 3.7: no warning. Effect: a row of three white spheres, a function call among them, and three small spheres below
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare Centre = <0,0.5,0>;
#declare R = 0.3;
#declare F = function(x) { x*0.05 }
#macro Size(S) (S*0.5) #end
#for (I, 0, 2)
  #declare Here = Centre + x*(I-1)*1.2;
  sphere { Here (R + F(I)) pigment { rgb 1 } }
  sphere { Here - y*1.2 Size(R) pigment { rgb <1,0.5,0> } }
#end
