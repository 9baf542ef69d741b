// LENIENCY switch_else_default: #else inside #switch acts as a default case when no earlier case is active (CASE_FALSE_COND -> CASE_TRUE_COND); when a case is already active it is a no-op and execution falls through into it
// POV-Ray 3.7: no warning. Effect: red sphere from the first switch (default), plus a red and a green sphere from the second (fall-through into #else)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare V = 7;
#switch (V)
  #case (1) sphere { 0, 1 pigment { rgb <0,0,1> } } #break
  #else     sphere { 0, 1 pigment { rgb <1,0,0> } }
#end
#declare V = 1;
#switch (V)
  #case (1) sphere { <-1.5,0.8,0>, 0.4 pigment { rgb <1,0,0> } }
  #else     sphere { < 1.5,0.8,0>, 0.4 pigment { rgb <0,1,0> } }
#end
