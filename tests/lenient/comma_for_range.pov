// LENIENCY comma_for_range: #for (I -1 1) and #range (1 5) without commas (Parse_For_Param, Parse_Cond_Param2 via Parse_Float_Param2)
// POV-Ray 3.7: no warning. Effect: three red spheres
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#for (I -1 1)
  #declare V = 3;
  #switch (V)
    #range (1 5) sphere { <I*1.5, 0, 0> 0.5 pigment { rgb <1,0,0> } } #break
    #else        sphere { <I*1.5, 0, 0> 0.5 pigment { rgb <0,0,1> } }
  #end
#end
