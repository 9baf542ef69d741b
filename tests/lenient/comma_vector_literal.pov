// LENIENCY comma_vector_literal: vector literals without commas and with a trailing comma: <1 0 0>, <1,0,0,>, <0.5,0.5,>, <1,0,0,0,>
// POV-Ray 3.7: no warning. Effect: red sphere; #debug prints the parsed vectors
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare A = <1 0 0>;
#declare B = <1,0,0,>;
#declare C = <0.5,0.5,>;
#declare D = <1,0,0,0,>;
#debug concat("A=", vstr(3,A,",",0,1), " B=", vstr(3,B,",",0,1), " C=", vstr(2,C,",",0,1), " D=", vstr(4,D,",",0,1), "\n")
sphere { 0 1 pigment { rgb B } }
