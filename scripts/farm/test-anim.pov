// The animation scripts/farm/parallel-test.sh and batch-test.sh render.
camera { location <0, 1.5, -5> look_at <0, 0.7, 0> }
light_source { <-4, 6, -6> color rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.9> rgb <0.2, 0.3, 0.6> } }
sphere { <-1.5 + 3 * clock, 0.8, 0>, 0.8
  pigment { rgb <0.9, 0.3, 0.2> } finish { specular 0.6 } }
