// LENIENCY deprecated_declare: #declare deprecated [once] "message" Name = ...; using the name prints the message (TF_DEPRECATED in Read_Symbol)
// POV-Ray 3.7: Warning "R is old, use Radius" (once). Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare deprecated once "R is old, use Radius" R = 1;
sphere { 0, R pigment { rgb <1,0,0> } }
sphere { 0, R pigment { rgb <1,0,0> } }
