// LENIENCY comma_read_write: #write and #read argument lists without commas; #read of a data file whose items are separated by commas (Parse_Write, Parse_Read, Parse_Read_Value). Writes lenient_rw.tmp in the working directory
// POV-Ray 3.7: no warning. Effect: red sphere of radius 1 read back from the file
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#fopen Out "lenient_rw.tmp" write
#write (Out "1," <1 0 0> ",\n")
#fclose Out
#fopen In "lenient_rw.tmp" read
#read (In R V)
#fclose In
#debug concat("R=", str(R 0 1), " V=", vstr(3 V "," 0 1), "\n")
sphere { 0 R pigment { rgb V } }
