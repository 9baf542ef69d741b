// s5: sphere sweeps - linear_spline, cubic_spline, b_spline, varying radii, tolerance, transforms, #while/#for-built coils, glass/phong/reflective finishes
#version 3.7;
#include "colors.inc"

global_settings { assumed_gamma 1.0 }

camera {
  perspective
  location <0, 4.5, -9>
  look_at <0, 1.2, 0>
  angle 48
}

light_source { <-8, 12, -10> color rgb <1, 1, 1> }
light_source { <10, 6, -4> color rgb <0.35, 0.35, 0.4> shadowless }

background { color rgb <0.55, 0.7, 0.9> }

// checkered floor
plane {
  y, 0
  pigment { checker color rgb <0.9, 0.9, 0.85> color rgb <0.25, 0.3, 0.35> scale 1 }
  finish { diffuse 0.8 ambient 0.1 reflection 0.05 }
}

// 1) linear_spline zig-zag with varying radii, rotated and translated (left)
sphere_sweep {
  linear_spline
  5,
  <-1.0, 0.0, 0>, 0.15,
  <-0.5, 1.0, 0>, 0.30,
  < 0.0, 0.0, 0>, 0.20,
  < 0.5, 1.0, 0>, 0.35,
  < 1.0, 0.0, 0>, 0.15
  texture {
    pigment { color rgb <0.85, 0.15, 0.1> }
    finish { phong 0.8 phong_size 60 diffuse 0.7 ambient 0.1 }
  }
  rotate <0, 30, 0>
  translate <-3.0, 0.35, 0.5>
}

// 2) cubic_spline coil built in a #while loop (centre), with tolerance
#declare NPts = 26;     // includes the two extra control points of a cubic spline
#declare CoilR = 1.0;
sphere_sweep {
  cubic_spline
  NPts,
  #declare I = 0;
  #while (I < NPts)
    #declare Ang = I * 50;           // degrees
    #declare T = I / (NPts - 1);
    <CoilR * cos(radians(Ang)), 0.15 * I, CoilR * sin(radians(Ang))>, 0.08 + 0.14 * T
    #declare I = I + 1;
  #end
  tolerance 1.0e-4
  texture {
    pigment { color rgb <0.95, 0.75, 0.2> }
    finish { phong 0.6 phong_size 40 reflection 0.25 metallic diffuse 0.6 ambient 0.1 }
  }
  translate <0, -0.1, 1.2>
}

// 3) b_spline wave built with #for, non-uniformly scaled (right)
sphere_sweep {
  b_spline
  9,
  #for (J, 0, 8)
    <0.4 * J - 1.6, 0.8 + 0.6 * sin(radians(J * 80)), 0.5 * cos(radians(J * 80))>, 0.18 + 0.04 * mod(J, 3)
  #end
  texture {
    pigment { color rgb <0.15, 0.45, 0.9> }
    finish { phong 1.0 phong_size 120 reflection 0.15 diffuse 0.7 ambient 0.1 }
  }
  scale <0.9, 1.4, 0.7>
  rotate <0, -25, 0>
  translate <3.0, 0, 0.3>
}

// 4) transparent glass-like linear sweep lying in the foreground
sphere_sweep {
  linear_spline
  3,
  <-1.5, 0, 0>, 0.25,
  < 0.0, 0, 0>, 0.45,
  < 1.5, 0, 0>, 0.25
  tolerance 0.001
  texture {
    pigment { color rgbf <0.9, 1.0, 0.95, 0.85> }
    finish { phong 0.9 phong_size 150 reflection 0.1 specular 0.5 ambient 0.0 diffuse 0.2 }
  }
  interior { ior 1.5 }
  rotate <0, 15, 0>
  translate <-0.2, 0.46, -2.2>
}

// 5) small b_spline arc scaled uniformly (behind, green)
sphere_sweep {
  b_spline
  6,
  <-2, 0, 0>, 0.3,
  <-1, 1.5, 0>, 0.4,
  < 0, 2.5, 0>, 0.25,
  < 1, 1.5, 0>, 0.4,
  < 2, 0, 0>, 0.3,
  < 3, -1, 0>, 0.3
  texture {
    pigment { color rgb <0.2, 0.75, 0.3> }
    finish { phong 0.5 diffuse 0.75 ambient 0.1 }
  }
  scale 1.1
  translate <-1.6, 0.2, 4.0>
}
