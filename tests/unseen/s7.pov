// s7: user-defined functions and function-based shapes. Exercises
//   #declare F = function { ... } and function(a, b, c) { ... } declarations
//   calling each other (sin, cos, pow, sqrt, abs, min, max, select, atan2,
//   mod), internal functions from functions.inc (f_sphere, f_torus,
//   f_rounded_box, f_superellipsoid, f_noise3d, f_snoise3d, f_r, f_th, f_ph,
//   f_ellipsoid, f_heart, f_paraboloid, f_torus2) with extra parameters,
//   three isosurfaces (sphere and box contained_by, threshold, accuracy,
//   max_gradient, one `open`), one parametric (precompute), and a
//   height_field built from a function with `smooth`, on a checkered floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#include "functions.inc"

// ---------------------------------------------------------------------
// Small helper functions with named parameters, calling each other
// ---------------------------------------------------------------------
#declare Sq     = function(a) { a*a }
#declare Hypot  = function(a, b) { sqrt(Sq(a) + Sq(b)) }
#declare Clamp  = function(a, lo, hi) { min(max(a, lo), hi) }
// polynomial smooth minimum of two distance-like values
#declare SMin   = function(a, b, k) {
  min(a, b) - pow(max(k - abs(a - b), 0), 2) / (4*k)
}
// twist around the y axis: rotate (px, pz) by an angle proportional to py
#declare TwistX = function(px, py, pz, k) { px*cos(k*py) - pz*sin(k*py) }
#declare TwistZ = function(px, py, pz, k) { px*sin(k*py) + pz*cos(k*py) }

// ---------------------------------------------------------------------
// Isosurface A: noisy blob (sphere + signed noise), smoothly joined with
// a small squashed ellipsoid "foot"
// ---------------------------------------------------------------------
#declare F_BlobCore = function { f_sphere(x, y, z, 0.95) }
#declare F_BlobNoise = function(px, py, pz, s) {
  0.22 * f_snoise3d(px*s, py*s, pz*s) + 0.06 * (f_noise3d(px*2*s, py*2*s, pz*2*s) - 0.5)
}
#declare F_Foot = function { f_ellipsoid(x, y + 0.85, z, 1/1.05, 1/0.3, 1/1.05) - 1 }
#declare F_Blob = function {
  SMin(F_BlobCore(x, y, z) + F_BlobNoise(x, y, z, 2.2), 0.8*F_Foot(x, y, z), 0.25)
}

// ---------------------------------------------------------------------
// Isosurface B: twisted rounded box, smoothly merged with a torus ring
// (rendered `open`: its container cuts off the top of the twisted box)
// ---------------------------------------------------------------------
#declare F_TwistBox = function {
  f_rounded_box(TwistX(x, y, z, 0.9), y, TwistZ(x, y, z, 0.9), 0.12, 0.5, 1.45, 0.5)
}
#declare F_Ring = function { f_torus(x, y + 0.25, z, 0.95, 0.16) }
#declare F_Tower = function { SMin(F_TwistBox(x, y, z), F_Ring(x, y, z), 0.3) }

// ---------------------------------------------------------------------
// Isosurface C: min/max combination of several shapes
//   - bumpy ball from spherical coordinates (f_r, f_th, f_ph), flattened by
//     max() with a superellipsoid "rounded cube"
//   - a ring from f_torus2 (field-strength function, positive inside)
//   - a small heart (f_heart) on top, positive inside as well
//   - a shallow star-shaped spike pattern around the equator via atan2/mod
// ---------------------------------------------------------------------
#declare F_Bumpy = function {
  f_r(x, y, z) - 0.82 - 0.07 * sin(6*f_th(x, y, z)) * sin(6*f_ph(x, y, z))
}
#declare F_RCube = function { -f_superellipsoid(x/0.78, y/0.78, z/0.78, 0.35, 0.35) }
#declare Sector = function(px, pz, n) {
  // position inside an angular sector, 0..1, via atan2 and mod
  mod(atan2(pz, px) / (2*pi) * n + 10*n, 1)
}
#declare F_Ball = function {
  max(F_Bumpy(x, y, z), 0.6*F_RCube(x, y, z))
    - 0.05 * Clamp(1 - 8*Sq(y), 0, 1) * abs(2*Sector(x, z, 8) - 1)
}
// the field-strength functions grow very fast away from their surface, so
// they are capped with min() to keep the gradient of the combination low
#declare F_Saturn = function { min(-0.5 * f_torus2(x, y*1.6, z, 1, 1.12, 0.09), 0.15) }
#declare F_Heart = function { min(-0.06 * f_heart(x/0.32, z/0.32, (y - 1.05)/0.32, 1), 0.03) }
#declare F_Combo = function {
  min(min(F_Ball(x, y, z), F_Saturn(x, y, z)), F_Heart(x, y, z))
}

// ---------------------------------------------------------------------
// Parametric: a ribbon torus whose elliptical cross section makes three
// half twists around the ring (a Moebius-like twisted band)
// ---------------------------------------------------------------------
#declare P_CA   = function(u, v) { 0.24*cos(v) }
#declare P_CB   = function(u, v) { 0.06*sin(v) }
#declare P_Off  = function(u, v) { P_CA(u, v)*cos(1.5*u) - P_CB(u, v)*sin(1.5*u) }
#declare P_Hgt  = function(u, v) { P_CA(u, v)*sin(1.5*u) + P_CB(u, v)*cos(1.5*u) }
#declare P_X    = function(u, v) { (0.62 + P_Off(u, v)) * cos(u) }
#declare P_Y    = function(u, v) { P_Hgt(u, v) }
#declare P_Z    = function(u, v) { (0.62 + P_Off(u, v)) * sin(u) }

// ---------------------------------------------------------------------
// Height field: noise terrain with a paraboloid valley, terraces (mod)
// and a flat lake level (select)
// ---------------------------------------------------------------------
#declare H_Hills = function(px, py) {
  0.42 + 0.6 * f_snoise3d(px*4, py*4, 0.3) + 0.12 * f_snoise3d(px*11, py*11, 1.7)
}
#declare H_Valley = function(px, py) {
  // f_paraboloid(x,y,z,P) = P*(y - x*x - z*z); with y=0, P=-1 it is x*x+z*z
  f_paraboloid(px - 0.5, 0, (py - 0.35)*0.6, -1)
}
// circular crater rim around (0.22, 0.62)
#declare H_Rim = function(px, py) {
  0.25 * Clamp(1 - 14*abs(Hypot(px - 0.22, py - 0.62) - 0.1), 0, 1)
}
// the last factor flattens the terrain towards the edge facing the camera
// (the function's y = 1 row ends up at z = 0 of the height field)
#declare H_Raw = function(px, py) {
  Clamp((H_Hills(px, py) * min(1, 0.35 + 6*H_Valley(px, py)) + H_Rim(px, py))
        * Clamp((1 - py)*6, 0, 1), 0, 1)
}
#declare H_Terrace = function(h) { h - 0.35 * mod(h, 0.1) }
#declare H_Final = function(px, py) {
  select(H_Raw(px, py) - 0.12, 0.12, H_Terrace(H_Raw(px, py)))
}

// ---------------------------------------------------------------------
// Scene
// ---------------------------------------------------------------------
camera {
  location <0, 3.8, -8.2>
  look_at  <0, 1.0, 0.5>
  angle 56
}

light_source { <-6, 12, -9> color rgb <1.0, 0.97, 0.92> }
light_source { <8, 6, -4> color rgb <0.35, 0.38, 0.45> shadowless }

background { color rgb <0.55, 0.7, 0.9> }

plane {
  y, 0
  texture {
    pigment { checker color rgb <0.85, 0.85, 0.8> color rgb <0.3, 0.32, 0.35> scale 1 }
    finish { ambient 0.05 diffuse 0.8 reflection 0.05 }
  }
}

// A: noisy blob (sphere container, threshold slightly above 0)
isosurface {
  function { F_Blob(x, y, z) }
  contained_by { sphere { 0, 1.45 } }
  threshold 0.02
  accuracy 0.001
  max_gradient 2.3
  texture {
    pigment { color rgb <0.85, 0.35, 0.2> }
    finish { ambient 0.05 diffuse 0.75 specular 0.4 roughness 0.02 }
  }
  translate <-2.7, 1.15, 0.2>
}

// B: twisted box + ring, open (box container cuts the top off)
isosurface {
  function { F_Tower(x, y, z) }
  contained_by { box { <-1.25, -1.5, -1.25>, <1.25, 0.95, 1.25> } }
  threshold 0
  accuracy 0.001
  max_gradient 1.4
  open
  texture {
    pigment { color rgb <0.3, 0.65, 0.35> }
    finish { ambient 0.05 diffuse 0.7 specular 0.5 roughness 0.01 phong 0.2 }
  }
  rotate y*20
  translate <0, 1.5, 0.9>
}

// C: min/max combination (bumpy ball, ring, heart)
isosurface {
  function { F_Combo(x, y, z) }
  contained_by { box { <-1.35, -0.95, -1.35>, <1.35, 1.45, 1.35> } }
  threshold 0
  accuracy 0.0005
  max_gradient 2.7
  texture {
    pigment { color rgb <0.35, 0.45, 0.9> }
    finish { ambient 0.05 diffuse 0.7 specular 0.6 roughness 0.01 reflection 0.08 }
  }
  rotate y*-25
  translate <2.75, 0.95, 0.2>
}

// parametric: small twisted ribbon torus in front
parametric {
  function { P_X(u, v) }
  function { P_Y(u, v) }
  function { P_Z(u, v) }
  <0, 0>, <2*pi, 2*pi>
  contained_by { box { <-0.88, -0.26, -0.88>, <0.88, 0.26, 0.88> } }
  max_gradient 1.5
  accuracy 0.01
  precompute 18 x, y, z
  texture {
    pigment { color rgb <0.95, 0.8, 0.2> }
    finish { ambient 0.05 diffuse 0.7 specular 0.6 roughness 0.02 metallic }
  }
  rotate x*-35
  translate <-0.6, 0.55, -2.3>
}

// terrain behind everything
height_field {
  function 80, 80 { H_Final(x, y) }
  smooth
  texture {
    pigment {
      gradient y
      color_map {
        [0.00 color rgb <0.2, 0.35, 0.6>]
        [0.13 color rgb <0.2, 0.35, 0.6>]
        [0.14 color rgb <0.45, 0.6, 0.25>]
        [0.55 color rgb <0.5, 0.42, 0.3>]
        [0.80 color rgb <0.95, 0.95, 0.95>]
      }
    }
    finish { ambient 0.05 diffuse 0.8 }
  }
  translate <-0.5, 0, 0>
  scale <20, 4, 8>
  translate <0, 0, 3.0>
}
