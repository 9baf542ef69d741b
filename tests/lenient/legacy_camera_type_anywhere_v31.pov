// LENIENCY legacy_camera_type_anywhere_v31: with #version < 3.5 the camera type keyword may come after other camera items (3.5+ requires it first: "Expected 'perspective camera modifier', orthographic found")
// POV-Ray 3.7: only the "language version set to 3.1 or earlier" and pre-3.7 gamma warnings. Effect: red sphere seen through an orthographic camera
#version 3.1;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 orthographic }
light_source { <-5,5,-5> color rgb 1 }
sphere { 0, 1 pigment { rgb <1,0,0> } }
