// LENIENCY bare_object_id: an object identifier alone at top level (or inside a CSG) is an object statement, no "object { }" needed (Parse_Object OBJECT_ID_TOKEN)
// POV-Ray 3.7: no warning. Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare S = sphere { 0, 1 pigment { rgb <1,0,0> } }
S
