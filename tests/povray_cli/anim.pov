// Prints the animation values; POV-Ray 3.7 prints, for +KFI1 +KFF10 +SF9 +EF10:
//   F 9 c 0.888889 d 0.111111 on 1 if 1 ff 10 ic 0.000 fc 1.000
//   F 10 c 1.000000 d 0.111111 on 1 if 1 ff 10 ic 0.000 fc 1.000
// and for +KFI1 +KFF3 +KC: F 3 c 0.666667 d 0.333333 on 1 if 1 ff 4 ic 0.000 fc 1.000
// anim.povray09.png and anim.povray10.png are POV-Ray's frames:
//   povray +Ianim.pov +Oanim.povray.png +W64 +H48 -A -D +KFI1 +KFF10 +SF9 +EF10
#version 3.7;
#debug concat("F ", str(frame_number,0,0), " c ", str(clock,0,6), " d ", str(clock_delta,0,6), " on ", str(clock_on,0,0), " if ", str(initial_frame,0,0), " ff ", str(final_frame,0,0), " ic ", str(initial_clock,0,3), " fc ", str(final_clock,0,3), "\n")
camera { location <0, 1, -4> look_at <0, 0.5, 0> }
light_source { <-3, 5, -4> rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb 0.3 } }
sphere { <-1.5 + 3*clock, 0.5, 0>, 0.5 pigment { rgb <1, 0.4, 0.2> } }
