// LENIENCY version_without_hash_nosemi: top-level "version 3.7" without "#" and without ";" parses normally (the unget then returns the next real token)
// POV-Ray 3.7: Possible Parse Error "All #version and #declares of float, vector, and color require semi-colon ';' at end.". Effect: red sphere
version 3.7
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { 0, 1 pigment { rgb <1,0,0> } }
