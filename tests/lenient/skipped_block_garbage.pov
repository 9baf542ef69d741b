// LENIENCY skipped_block_garbage: inside a false #if, tokens are read but not parsed: unknown directives, unbalanced brackets and undeclared words are ignored (but the text must still tokenize: bad numbers like 1.2.3 or non-ASCII bytes are still fatal)
// POV-Ray 3.7: no warning. Effect: red sphere
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#if (0)
  this is { not ] valid ) syntax at all #local #undef_whatever
  #bogus_directive $ @ ` ~ '
#end
sphere { 0, 1 pigment { rgb <1,0,0> } }
