// LENIENCY comma_point_lists: count-driven point lists without commas: polygon, prism (heights and count too), lathe, sor, sphere_sweep (Parse_Polygon/Parse_Prism/Parse_Lathe/Parse_Sor/Parse_Sphere_Sweep call Parse_Comma before every point)
// POV-Ray 3.7: no warning. Effect: five red objects
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
polygon { 5 <-1,-1> <1,-1> <1,1> <-1,1> <-1,-1> pigment { rgb <1,0,0> } scale 0.5 translate <-1.2,0.8,0> }
prism { 0 1 5 <-1,-1> <1,-1> <1,1> <-1,1> <-1,-1> pigment { rgb <1,0,0> } scale 0.4 rotate -x*90 translate <0,0.8,0> }
lathe { linear_spline 3 <0,0> <0.5,0.5> <0,1> pigment { rgb <1,0,0> } translate <1.2,0.4,0> }
sor { 4 <0,0> <0.5,0> <0.3,1> <0,1.2> pigment { rgb <1,0,0> } translate <-1.2,-1.2,0> }
sphere_sweep { linear_spline 2 <-0.5,-1,0> 0.2 <0.5,-1,0> 0.3 pigment { rgb <1,0,0> } }
