// LENIENCY comma_mesh_triangles: triangle / smooth_triangle corners without commas (commas kept only before negative vectors)
// POV-Ray 3.7: no warning. Effect: red hourglass of two triangles
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
mesh {
  triangle { <-1,-1,0> <1,-1,0> <0,1,0> }
  smooth_triangle { <-1,1,0.1>, -z <1,1,0.1>, -z <0,-1,0.1>, -z }
  pigment { rgb <1,0,0> }
}
