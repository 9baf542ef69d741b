// LENIENCY string_compare_cond: string comparisons (<, =, !=, ...) inside #if / parenthesised expressions (Parse_Rel_Term tries Parse_String first)
// POV-Ray 3.7: no warning. Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare N = "abc";
#if ((N < "abd") & (N = "abc") & ("x" != "y")) sphere { 0, 1 pigment { rgb <1,0,0> } } #end
