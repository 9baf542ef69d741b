// LENIENCY version_without_hash_truncates: top-level "version 3.7;" without "#": Parse_Frame calls Parse_Directive(false) then UNGETs the END_OF_FILE_TOKEN it leaves behind, so parsing STOPS there and the rest of the file is silently ignored
// POV-Ray 3.7: Warning "No objects in scene." (nothing after the version line is parsed: no camera, light, background or sphere). Effect: all-black image
version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
sphere { 0, 1 pigment { rgb <1,0,0> } }
