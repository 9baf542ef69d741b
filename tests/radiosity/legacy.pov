// A scene for POV-Ray 3.6: with radiosity on, its `ambient` still lights surfaces (3.7 drops
// it), and an area light is seen by radiosity's rays as a point.
#version 3.6;
global_settings { assumed_gamma 1.0 radiosity { count 60 error_bound 1.2 recursion_limit 1 gray_threshold 0.3 brightness 1.4 } }
camera { location <0, 1.2, -4> look_at <0, 0.8, 0> }
light_source { <1, 2.5, -1> rgb 1 area_light x*0.8, z*0.8, 4, 4 adaptive 1 }
plane { y, 0 pigment { rgb <0.9, 0.8, 0.6> } finish { ambient 0.1 diffuse 0.7 } }
plane { z, 2 pigment { rgb <0.3, 0.5, 0.9> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <0, 0.6, 0.4>, 0.6 pigment { rgb 0.9 } finish { ambient 0.2 diffuse 0.6 phong 0.8 } }
cylinder { <-1.3, 0, 0.6>, <-1.3, 1.4, 0.6>, 0.25 pigment { rgb <0.9, 0.2, 0.2> } finish { ambient 0.1 } }
