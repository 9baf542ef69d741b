// LENIENCY comma_mesh2: mesh2 lists without commas: vertex_vectors, normal_vectors, texture_list, face_indices with per-face texture indices, normal_indices
// POV-Ray 3.7: no warning. Effect: square split into a red and a blue triangle
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
mesh2 {
  vertex_vectors { 4 <-1,-1,0> <1,-1,0> <1,1,0> <-1,1,0> }
  normal_vectors { 1, -z }          // comma needed: "1 -z" would be 1-z
  texture_list   { 2 texture { pigment { rgb <1,0,0> } } texture { pigment { rgb <0,0,1> } } }
  face_indices   { 2 <0,1,2> 0 <0,2,3> 1 }
  normal_indices { 2 <0,0,0> <0,0,0> }
}
