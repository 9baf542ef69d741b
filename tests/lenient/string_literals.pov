// LENIENCY string_literals: string literals may contain raw newlines; escapes \t \" \\ \' \uXXXX; \u takes the next 4 chars and strtoul stops at the first non-hex one ("\u41zz" -> "A", the "zz" is consumed)
// POV-Ray 3.7: no warning. Effect: red sphere; #debug shows the strings
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare S = "line1
line2";
#debug concat(S, "\n")
#debug concat("tab[\t] quote[\"] bs[\\] apos[\'] u[\u0041] short[\u41zz]\n")
sphere { 0, 1 pigment { rgb <1,0,0> } }
