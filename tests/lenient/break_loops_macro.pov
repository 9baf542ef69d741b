// LENIENCY break_loops_macro: #break ends #while and #for loops and also returns early from a macro (Break() stops at WHILE_COND, FOR_COND, CASE_TRUE_COND or INVOKING_MACRO_COND); outside those it is "Invalid context for #break"
// POV-Ray 3.7: no warning. Effect: three red spheres in a row (loops broken after 3), macro draws only its first sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare I = 0;
#while (1)
  #if (I = 3) #break #end
  sphere { <-1.5 + I*1.5, 0.8, 0>, 0.4 pigment { rgb <1,0,0> } }
  #declare I = I + 1;
#end
#for (J, 0, 10)
  #if (J > 2) #break #end
  sphere { <-1.5 + J*1.5, -0.8, 0>, 0.4 pigment { rgb <1,0,0> } }
#end
#macro M(R)
  sphere { 0, R pigment { rgb <1,0,0> } }
  #break
  sphere { 0, 2*R pigment { rgb <0,0,1> } }
#end
M(0.3)
