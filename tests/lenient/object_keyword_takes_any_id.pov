// LENIENCY object_keyword_takes_any_id: any object keyword followed by an object identifier copies that object, whatever its type (Parse_Object_Id): sphere { BoxId } is a box
// POV-Ray 3.7: no warning. Effect: rotated red box
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare B = box { -0.7, 0.7 pigment { rgb <1,0,0> } }
sphere { B rotate <30,30,0> }
