// s4_showroom.pov - a tile showroom: sample boards hung on a wall, each a pavement
// or tiling variant, plus fractal-decorated vases with fractal normals.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.7, -8.6> look_at <0, 1.7, 0> angle 64 }
light_source { <-3, 5, -6> rgb 1 }
light_source { <4, 2, -5> rgb 0.35 }
plane { -z, -0.2 pigment { rgb 0.5 } }
plane { y, -0.5 pigment { checker rgb 0.3 rgb 0.25 } }

#declare Cmap = color_map { [0 rgb <0.1, 0.1, 0.1>] [0.15 rgb <0.5, 0.3, 0.2>] [0.5 rgb <0.9, 0.8, 0.5>] [1 rgb <0.95, 0.95, 1>] }

#macro Board(Pat, I)
  box { <-0.45, -0.45, -0.05>, <0.45, 0.45, 0>
    texture { pigment { Pat rotate 90*x scale 0.12 } finish { ambient 0.2 } }
    translate <-4.5 + mod(I, 10) * 1.0, 3.6 - div(I, 10) * 1.0, 0> }
#end

// row 0-1: triangles (tiles 1..6), squares (tiles 1..5), hexagons 1..5 with a pattern each
#declare I = 0;
#declare M3 = array[6] {1,1,1,3,4,12}
#declare M4 = array[5] {1,1,2,5,12}
#declare M6 = array[5] {1,1,3,7,22}
#declare T = 1;
#while (T <= 6)
  Board(pigment { pavement number_of_sides 3 number_of_tiles T pattern M3[T-1] form mod(T, 3) exterior mod(T, 3) interior mod(T+1, 3) color_map { Cmap } }, I)
  #declare I = I + 1; #declare T = T + 1;
#end
#declare T = 1;
#while (T <= 5)
  Board(pigment { pavement number_of_sides 4 number_of_tiles T pattern M4[T-1] form mod(T, 4) interior mod(T, 3) color_map { Cmap } }, I)
  #declare I = I + 1; #declare T = T + 1;
#end
#declare T = 1;
#while (T <= 5)
  Board(pigment { pavement number_of_sides 6 number_of_tiles T pattern M6[T-1] form mod(T, 3) exterior mod(T, 3) color_map { Cmap } }, I)
  #declare I = I + 1; #declare T = T + 1;
#end
// high pattern numbers
Board(pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 12 color_map { Cmap } }, I) #declare I = I + 1;
Board(pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 12 form 3 color_map { Cmap } }, I) #declare I = I + 1;
Board(pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 7 color_map { Cmap } }, I) #declare I = I + 1;
Board(pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 22 color_map { Cmap } }, I) #declare I = I + 1;
// tilings with wave shapes and turbulence
Board(pigment { tiling 3 triangle_wave frequency 2 color_map { Cmap } }, I) #declare I = I + 1;
Board(pigment { tiling 9 turbulence 0.1 color_map { Cmap } }, I) #declare I = I + 1;
Board(pigment { tiling 13 warp { repeat 1.5*x flip x } color_map { Cmap } }, I) #declare I = I + 1;
Board(pigment { tiling 16 sine_wave color_map { Cmap } }, I) #declare I = I + 1;
Board(pigment { tiling 21 warp { black_hole <0, 0, 0>, 1 strength 2 } color_map { Cmap } }, I) #declare I = I + 1;
Board(pigment { tiling 27 poly_wave 2 color_map { Cmap } }, I) #declare I = I + 1;
Board(pigment { tiling 1 phase 0.3 color_map { Cmap } }, I) #declare I = I + 1;
Board(pigment { tiling 6 scale 2 color_map { Cmap } }, I) #declare I = I + 1;

// row 3: fractal boards
Board(pigment { mandel 30 interior 2, 1 exterior 4, 0.2 scale 3 translate <0.5, 0, 0> rotate -90*x color_map { Cmap } }, 30)
Board(pigment { mandel 30 exponent 4 interior 3, 1 exterior 5, 0.5 scale 3 rotate -90*x color_map { Cmap } }, 31)
Board(pigment { mandel 30 exponent 5 interior 4, 2 exterior 6, 0.05 scale 3 rotate -90*x color_map { Cmap } }, 32)
Board(pigment { julia <0.3, 0.5>, 30 interior 5, 0.5 exterior 7, 1 scale 3 rotate -90*x color_map { Cmap } }, 33)
Board(pigment { julia <-0.1, 0.65>, 40 exponent 3 interior 6, 1 exterior 8, 1 scale 3 rotate -90*x color_map { Cmap } }, 34)
Board(pigment { magnet 1 mandel 30 exterior 1, 0.3 scale 2 translate <0.5, 0, 0> rotate -90*x color_map { Cmap } }, 35)
Board(pigment { magnet 1 julia <1.2, 0.3>, 30 interior 1, 1 scale 2 rotate -90*x color_map { Cmap } }, 36)
Board(pigment { magnet 2 mandel 30 interior 2, 0.5 scale 2 rotate -90*x color_map { Cmap } }, 37)
Board(pigment { julia <0.285, 0.01>, 80 exponent 2 exterior 2, 0.5 scale 2.5 rotate -90*x color_map { Cmap } }, 38)
Board(pigment { mandel 25 exponent 33 scale 4 rotate -90*x color_map { Cmap } }, 39)

// vases with fractal normals
#declare V = 0;
#while (V < 3)
  sphere { 0, 0.5 scale <1, 1.3, 1>
    texture {
      pigment { rgb <0.6 + 0.2*V, 0.5, 0.8 - 0.2*V> }
      #switch (V)
        #case (0) normal { mandel 40 1.5 scale 0.4 } #break
        #case (1) normal { julia <0.353, 0.288>, 40 bump_size 1 scale 0.5 rotate 90*x } #break
        #case (2) normal { magnet 1 mandel 30 0.8 scale 0.3 turbulence 0.1 } #break
      #end
      finish { phong 0.7 phong_size 50 specular 0.2 }
    }
    translate <-2 + 2*V, 0.3, -1.8> }
  #declare V = V + 1;
#end
