// s6_stage.pov - a theatre stage: spotlights with looks_like housings, a gobo
// (projected_through a perforated plate), declared light groups placed twice,
// nested groups, a union of lights moved as one rig, and hidden helpers.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 3, -9> look_at <0, 1.2, 0> angle 58 }
light_source { <0, 8, -10> rgb 0.25 }

plane { y, 0 pigment { checker rgb <0.3, 0.2, 0.15> rgb <0.25, 0.17, 0.12> scale 0.5 } finish { reflection 0.1 specular 0.3 } }
box { <-6, 0, 3>, <6, 5, 3.2> pigment { rgb <0.5, 0.1, 0.12> } }

// a rig: a union of two coloured spotlights with housings, moved and turned as one
#declare Rig = union {
  light_source { <-0.6, 0, 0> rgb <1.2, 0.4, 0.3> spotlight point_at <-0.6, -4, 3> radius 12 falloff 20 tightness 5
    looks_like { cylinder { <0, 0, 0>, <0, 0.3, 0>, 0.15 pigment { rgb 0.1 } finish { ambient 0 } } } }
  light_source { <0.6, 0, 0> rgb <0.3, 0.5, 1.4> spotlight point_at <0.6, -4, 3> radius 12 falloff 20 tightness 5
    looks_like { cylinder { <0, 0, 0>, <0, 0.3, 0>, 0.15 pigment { rgb 0.1 } finish { ambient 0 } } } }
  box { <-1, 0.3, -0.1>, <1, 0.4, 0.1> pigment { rgb 0.3 } }
}
object { Rig translate <-1.5, 4, -1> }
object { Rig rotate 10*y translate <1.5, 4, -1> }

// a gobo: a spot that only passes through a star-pierced plate (the plate itself hidden)
#declare Plate = union {
  sphere { <0, 0, 0>, 0.12 }
  sphere { <0.25, 0.1, 0>, 0.08 }
  sphere { <-0.2, 0.15, 0>, 0.07 }
  sphere { <0.05, -0.22, 0>, 0.09 }
}
light_source { <0, 0, 0> rgb 1.5
  projected_through { Plate translate <0, 0, 1> }
  rotate 40*x translate <0, 5, -3> }

// actors
sphere { <-1.8, 0.6, 0.5>, 0.6 pigment { rgb 0.9 } finish { phong 0.6 } }
sphere { <1.8, 0.6, 0.5>, 0.6 pigment { rgb 0.9 } finish { phong 0.6 } }
cylinder { <0, 0, 1.2>, <0, 1.8, 1.2>, 0.35 pigment { rgb <0.9, 0.85, 0.7> } }

// a declared group: a footlight and its prop, placed twice
#declare Foot = light_group {
  light_source { <0, 0.3, -0.6> rgb <1, 0.9, 0.4> }
  sphere { <0, 0.25, 0>, 0.25 pigment { rgb 1 } finish { phong 0.9 } }
  box { <-0.3, 0, 0.2>, <0.3, 0.5, 0.3> pigment { rgb <0.2, 0.7, 0.3> } }
}
object { Foot translate <-3.5, 0, -1.5> }
object { Foot rotate 30*y translate <3.5, 0, -1.5> }

// nested groups: the inner light lights only the inner object, the outer both
light_group {
  light_source { <0, 3, -2> rgb <0.2, 1, 0.2> }
  box { <-0.4, 0, -2.8>, <0.4, 0.3, -2.2> pigment { rgb 1 } }
  light_group {
    light_source { <1, 2, -3> rgb <1, 0.2, 1> }
    sphere { <0, 0.6, -2.5>, 0.3 pigment { rgb 1 } }
  }
}
// a hidden shadow caster and a reflection-only marker
box { <-0.3, 3.2, -0.3>, <0.3, 3.3, 0.3> pigment { rgb 1 } no_image no_reflection rotate 20*y translate <-1.5, 0, 0> }
sphere { <2.6, 0.25, -0.5>, 0.25 pigment { rgb <1, 1, 0> } no_image }
