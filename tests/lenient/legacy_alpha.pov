// LENIENCY legacy_alpha: colour keyword alpha (pre-2.0) is accepted as filter
// POV-Ray 3.7: Warning "Keyword ALPHA discontinued. Use FILTER instead." (level 155: silent for #version <= 1.55). Effect: red, strongly filtering sphere; #debug shows filter 0.3 in slot 4
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare E = color red 1 blue 0.5 alpha 0.3;
#debug concat("E=", vstr(5, E, ",", 0, 2), "\n")
sphere { 0, 1 pigment { color red 1 alpha 0.9 } }
