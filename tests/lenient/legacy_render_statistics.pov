// LENIENCY legacy_render_statistics: #render and #statistics message directives are accepted and redirected to #debug
// POV-Ray 3.7: Warning "#render and #statistics streams are no longer available. Redirecting output to #debug stream." (each). Effect: red sphere; the two messages are printed
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#render "hello render\n"
#statistics "hello stats\n"
sphere { 0, 1 pigment { rgb <1,0,0> } }
