// LENIENCY comma_shapes: no commas between the parameters of sphere, box, cone, cylinder, torus, disc (Parse_Sphere/Parse_Box/Parse_Cone/Parse_Cylinder/Parse_Torus/Parse_Disc call Parse_Comma)
// POV-Ray 3.7: no warning. Effect: six red shapes
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
union {
  sphere   { <-1.5,0.8,0> 0.4 }
  box      { <-0.3,0.5,-0.3> <0.3,1.1,0.3> }
  cone     { <1.5,0.5,0> 0.4 <1.5,1.1,0> 0 }
  cylinder { <-1.5,-1,0> <-1.5,-0.4,0> 0.3 open }
  torus    { 0.4 0.1 rotate x*90 translate <0,-0.7,0> }
  disc     { <1.5,-0.7,0>, -z 0.4 0.1 }   // comma needed before -z (see comma_minus_gotcha)
  pigment  { rgb <1,0,0> }
}
