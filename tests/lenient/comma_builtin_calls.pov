// LENIENCY comma_builtin_calls: built-in function arguments without commas: vcross, pow, mod, atan2, strcmp, substr, concat, vdot, vrotate, vaxis_rotate, str, vstr, trace, inside, dimension_size, vturbulence (trailing comma allowed), select (first two only)
// POV-Ray 3.7: no warning. Effect: red sphere of radius 1; #debug lines show the results
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-4> look_at 0 }
light_source { <-5,5,-5> color rgb 1 }
background { rgb 0.2 }
#declare V1 = vcross(x y);
#declare R  = pow(2 0) * mod(5 3) / 2 * atan2(1 1) * 4 / pi;
#debug concat("R=", str(R 0 3), " V1=", vstr(3 V1 "," 0 1), " cmp=", str(strcmp("a" "a") 0 0), " sub=", substr("hello" 2 3), " cat=", concat("a" "b" "c"), "\n")
#debug concat("vdot=", str(vdot(x x) 0 1), " vrot=", vstr(3 vrotate(x <0 0 90>) "," 0 1), " vax=", vstr(3 vaxis_rotate(x z 90) "," 0 1), "\n")
#declare S = sphere { 0 1 }
#debug concat("trace=", vstr(3 trace(S <0,0,-5> z) "," 0 1), " inside=", str(inside(S 0) 0 0), " sel=", str(select(-1 1 2, 3) 0 0), "\n")
#declare A = array[2][3];
#debug concat("dimsize=", str(dimension_size(A 2) 0 0), " vturb=", vstr(3 vturbulence(2 0.5 6 <0 0 0>,) "," 0 2), "\n")
sphere { 0 R pigment { rgb <1,0,0> } }
