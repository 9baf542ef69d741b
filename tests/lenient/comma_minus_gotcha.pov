// LENIENCY comma_minus_gotcha: commas are optional, so a "-" after a value is BINARY minus: <1 -1 0> is <1-1, 0> = the 2-vector <0,0> (then promoted to <0,0,0>)
// POV-Ray 3.7: no warning. Effect: the sphere is at the centre, not at <1,-1,0>; #debug shows the vectors
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare V = <1 -1 0>;
#declare W = <1, -1, 0>;
#debug concat("V=", vstr(3,V,",",0,1), " W=", vstr(3,W,",",0,1), "\n")
sphere { V 0.6 pigment { rgb <1,0,0> } }
