// s6: blobs with per-component textures - sphere/cylinder components, strengths, threshold, component transforms, declared blob reused twice
#version 3.7;
#include "colors.inc"

global_settings { assumed_gamma 1.0 }

camera {
  perspective
  location <0, 5, -10>
  look_at <0, 1.3, 0>
  angle 42
}

light_source { <-10, 14, -12> color rgb <1, 1, 1> }
light_source { <8, 8, -6> color rgb <0.3, 0.3, 0.35> }

background { color rgb <0.6, 0.65, 0.75> }

plane {
  y, 0
  pigment { checker color rgb <0.85, 0.85, 0.8> color rgb <0.35, 0.25, 0.2> scale 1.2 }
  finish { diffuse 0.8 ambient 0.1 }
}

#declare Creature = blob {
  threshold 0.6
  // body: two large spheres, no own texture (take the blob's texture)
  sphere { <0, 1.2, 0>, 1.3, strength 1.0 }
  sphere { <0.9, 1.4, 0>, 1.0, 1.0 }
  // head with its own pigment
  sphere { <1.8, 2.0, 0>, 0.9, strength 1.2
    pigment { color rgb <0.9, 0.6, 0.1> }
  }
  // eye bump with a full texture
  sphere { <2.2, 2.3, -0.45>, 0.35, strength 1.5
    texture {
      pigment { color rgb <0.95, 0.95, 0.95> }
      finish { phong 1.0 phong_size 100 ambient 0.15 diffuse 0.7 }
    }
  }
  // tail: cylinder with a checker pigment, then a rotation applied to component and pigment
  cylinder { <-0.8, 1.0, 0>, <-2.4, 1.0, 0>, 0.45, strength 1.0
    pigment { checker color rgb <0.1, 0.7, 0.2> color rgb <0.95, 0.9, 0.2> scale 0.2 }
    rotate <0, 0, -25>
  }
  // legs: cylinders with no own texture
  cylinder { <-0.5, 1.0, -0.5>, <-0.6, 0.1, -0.6>, 0.35, 1.0 }
  cylinder { < 0.7, 1.0, -0.5>, < 0.8, 0.1, -0.6>, 0.35, 1.0 }
  cylinder { <-0.5, 1.0,  0.5>, <-0.6, 0.1,  0.6>, 0.35, 1.0 }
  cylinder { < 0.7, 1.0,  0.5>, < 0.8, 0.1,  0.6>, 0.35, 1.0 }
  // a negative-strength component carving the belly
  sphere { <0.2, 0.2, 0>, 0.7, strength -0.8 }
  // stripy crest: cylinder with its own texture (gradient) then scaled and translated
  cylinder { <0, 0, 0>, <1.2, 0, 0>, 0.3, strength 1.0
    texture {
      pigment { gradient x color_map { [0 color rgb <0.8, 0.1, 0.5>] [0.5 color rgb <0.2, 0.2, 0.9>] [1 color rgb <0.8, 0.1, 0.5>] } scale 0.3 }
      finish { specular 0.6 roughness 0.02 ambient 0.1 diffuse 0.7 }
    }
    scale <1, 1.3, 1>
    translate <-0.5, 2.05, 0>
  }
  // blob-wide texture for components without their own
  texture {
    pigment { color rgb <0.25, 0.55, 0.85> }
    finish { phong 0.7 phong_size 50 ambient 0.1 diffuse 0.7 }
  }
}

object { Creature translate <-2.2, 0, 0.5> }
object { Creature scale 0.85 rotate <0, 150, 0> translate <2.5, 0, 1.0> }

// a small plain blob with a reflective finish on the blob as a whole
blob {
  threshold 0.5
  sphere { <-0.5, 0, 0>, 0.8, 1 }
  sphere { < 0.5, 0, 0>, 0.8, 1 }
  sphere { < 0, 0.6, 0>, 0.7, strength 1 }
  pigment { color rgb <0.75, 0.1, 0.1> }
  finish { reflection 0.3 phong 0.9 ambient 0.1 diffuse 0.6 }
  translate <0.2, 0.35, -2.6>
}
