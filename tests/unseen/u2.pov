// Room corner: bookshelf, side table with lamp, rug and a painting
// POV-Ray 3.7 scene
#version 3.7;

global_settings { assumed_gamma 1.0 max_trace_level 5 }

#include "colors.inc"
#include "textures.inc"
#include "woods.inc"
#include "stones.inc"
#include "metals.inc"

// room: left wall at x = -3, back wall at z = 3, floor y = 0, ceiling y = 3.2
#declare RoomW = 3;
#declare RoomH = 3.2;

camera {
  location <2.3, 1.7, -3.2>
  look_at  <-0.9, 1.05, 1.5>
  right    x*4/3
  up       y
  angle    62
}

// ceiling panel light (the single area light in this test set)
light_source {
  <0, RoomH - 0.15, 0>
  color rgb <1.0, 0.95, 0.85> * 0.85
  area_light <1.2, 0, 0>, <0, 0, 1.2>, 3, 3
  adaptive 1
}
// daylight falling in through the window
light_source {
  <1.85, 2.3, 2.85>
  color rgb <0.45, 0.5, 0.6>
  spotlight
  point_at <0.2, 0, 0.5>
  radius 25
  falloff 40
  tightness 5
}

// ---------------------------------------------------------------
// Floor: planks made of alternating wood pigments
// ---------------------------------------------------------------
#declare PlankWood1 = pigment { DMFWood4 scale <4, 4, 1> }
#declare PlankWood2 = pigment { Tom_Wood scale <0.2, 0.2, 3> }

plane {
  y, 0
  texture {
    pigment {
      gradient x
      pigment_map {
        [0.00 PlankWood1]
        [0.48 PlankWood1]
        [0.50 color rgb <0.15, 0.08, 0.04>]
        [0.52 PlankWood2]
        [1.00 PlankWood2]
      }
      scale 0.5
    }
    finish { phong 0.3 phong_size 40 reflection 0.05 ambient 0.05 }
  }
}

plane { -y, -RoomH pigment { color rgb <0.92, 0.9, 0.86> } finish { ambient 0.25 diffuse 0.6 } }

// ---------------------------------------------------------------
// Walls: brick on the back wall, striped wallpaper on the left
// ---------------------------------------------------------------
#declare BackWall = plane {
  -z, -RoomW
  texture {
    pigment {
      brick color rgb <0.75, 0.72, 0.66>, color rgb <0.55, 0.22, 0.14>
      brick_size <0.5, 0.17, 0.25>
      mortar 0.02
    }
    normal { brick 0.4 brick_size <0.5, 0.17, 0.25> mortar 0.02 }
    finish { ambient 0.08 diffuse 0.75 }
  }
  texture {
    pigment {
      granite
      color_map {
        [0.0 color rgbt <0.3, 0.2, 0.15, 0.85>]
        [1.0 color rgbt <0.9, 0.9, 0.9, 1.0>]
      }
      scale 0.3
    }
  }
}
object { BackWall }

plane {
  x, -RoomW
  texture {
    pigment {
      gradient z
      color_map {
        [0.0 color rgb <0.62, 0.7, 0.58>]
        [0.6 color rgb <0.62, 0.7, 0.58>]
        [0.6 color rgb <0.85, 0.82, 0.7>]
        [1.0 color rgb <0.85, 0.82, 0.7>]
      }
      scale 0.35
    }
    normal { bumps 0.05 scale 0.02 }
    finish { ambient 0.08 diffuse 0.7 }
  }
}

// baseboards
#declare Baseboard = texture { T_Wood14 scale 0.3 finish { phong 0.5 } }
box { <-RoomW, 0, RoomW - 0.04>, <RoomW, 0.15, RoomW> texture { Baseboard } }
box { <-RoomW, 0, -RoomW>, <-RoomW + 0.04, 0.15, RoomW> texture { Baseboard rotate y*90 } }

// ---------------------------------------------------------------
// Window on the back wall: frame boxes with a glowing sky behind
// ---------------------------------------------------------------
#declare WinX = 1.2;
#declare WinY = 1.1;
#declare WinW = 1.3;
#declare WinH = 1.4;
#declare FrameTex = texture { pigment { White } finish { phong 0.4 ambient 0.1 } }
union {
  // sky pane
  box {
    <WinX, WinY, RoomW - 0.03>, <WinX + WinW, WinY + WinH, RoomW - 0.02>
    pigment { Bright_Blue_Sky scale 0.4 }
    finish { ambient 0.9 diffuse 0 }
  }
  box { <WinX - 0.08, WinY - 0.1, RoomW - 0.12>, <WinX + WinW + 0.08, WinY, RoomW> }
  box { <WinX - 0.08, WinY + WinH, RoomW - 0.08>, <WinX + WinW + 0.08, WinY + WinH + 0.08, RoomW> }
  box { <WinX - 0.08, WinY, RoomW - 0.08>, <WinX, WinY + WinH, RoomW> }
  box { <WinX + WinW, WinY, RoomW - 0.08>, <WinX + WinW + 0.08, WinY + WinH, RoomW> }
  box { <WinX + WinW/2 - 0.03, WinY, RoomW - 0.06>, <WinX + WinW/2 + 0.03, WinY + WinH, RoomW - 0.03> }
  box { <WinX, WinY + WinH/2 - 0.03, RoomW - 0.06>, <WinX + WinW, WinY + WinH/2 + 0.03, RoomW - 0.03> }
  texture { FrameTex }
}

// ---------------------------------------------------------------
// Painting on the left wall
// ---------------------------------------------------------------
union {
  box {
    <-RoomW, 1.4, -0.2>, <-RoomW + 0.02, 2.2, 0.9>
    pigment { Apocalypse scale 0.3 warp { turbulence 0.4 } }
    finish { ambient 0.15 }
  }
  union {
    box { <-RoomW, 1.33, -0.27>, <-RoomW + 0.06, 1.4, 0.97> }
    box { <-RoomW, 2.2, -0.27>, <-RoomW + 0.06, 2.27, 0.97> }
    box { <-RoomW, 1.33, -0.27>, <-RoomW + 0.06, 2.27, -0.2> }
    box { <-RoomW, 1.33, 0.9>, <-RoomW + 0.06, 2.27, 0.97> }
    texture { T_Gold_3B }
  }
}

// ---------------------------------------------------------------
// Bookshelf against the left wall
// ---------------------------------------------------------------
#declare ShelfTex = texture { T_Wood7 scale 0.4 rotate x*90 }
#declare ShelfX0 = -RoomW;
#declare ShelfX1 = -RoomW + 0.4;
#declare ShelfZ0 = 1.3;
#declare ShelfZ1 = 2.8;

#macro Book(Z, Y, W, H, Col)
  box {
    <ShelfX0 + 0.04, Y, Z>, <ShelfX1 - 0.04 - 0.05 * mod(H * 100, 2), Y + H, Z + W>
    pigment { color Col }
    normal { dents 0.1 scale 0.03 }
    finish { phong 0.25 ambient 0.08 }
  }
#end

union {
  box { <ShelfX0, 0, ShelfZ0>, <ShelfX1, 2.0, ShelfZ0 + 0.04> }
  box { <ShelfX0, 0, ShelfZ1 - 0.04>, <ShelfX1, 2.0, ShelfZ1> }
  #for (S, 0, 4)
    box { <ShelfX0, S * 0.48, ShelfZ0>, <ShelfX1, S * 0.48 + 0.04, ShelfZ1> }
  #end
  texture { ShelfTex }
}

// books on three shelves
#for (S, 1, 3)
  #declare Z = ShelfZ0 + 0.06;
  #declare B = 0;
  #while (Z < ShelfZ1 - 0.2)
    #declare W = 0.05 + 0.02 * mod(B * 7 + S, 3);
    #declare H = 0.3 + 0.03 * mod(B * 5 + S * 2, 4);
    #declare Col = <0.2 + 0.6 * mod(B * 3 + S, 4) / 3,
                    0.15 + 0.2 * mod(B + S * 2, 3) / 2,
                    0.1 + 0.5 * mod(B * 2 + S, 5) / 4>;
    #if (mod(B + S, 7) = 3)
      // an old pale paperback
      object { Book(Z, S * 0.48 + 0.04, W, H * 0.8, rgb <0.85, 0.8, 0.65>) }
    #else
      object { Book(Z, S * 0.48 + 0.04, W, H, rgb Col) }
    #end
    #declare Z = Z + W + 0.01;
    #declare B = B + 1;
  #end
#end

// a stone bookend sphere on the top shelf
sphere { <-RoomW + 0.2, 2.14, 2.2>, 0.1 texture { T_Stone3 scale 0.3 } }

// ---------------------------------------------------------------
// Round side table with lamp
// ---------------------------------------------------------------
#declare TableTex = texture { T_Wood19 scale 0.3 rotate x*90 finish { phong 0.6 reflection 0.05 } }
union {
  cylinder { <0, 0.7, 0>, <0, 0.74, 0>, 0.5 }
  torus { 0.5, 0.02 translate y*0.72 }
  #for (L, 0, 2)
    cylinder { <0.3, 0, 0>, <0.2, 0.7, 0>, 0.03 rotate y*(L * 120 + 30) }
  #end
  texture { TableTex }
  translate <-1.6, 0, 0.7>
}

// lamp
union {
  union {
    cylinder { <0, 0, 0>, <0, 0.03, 0>, 0.14 }
    cylinder { <0, 0, 0>, <0, 0.45, 0>, 0.02 }
    sphere { <0, 0.12, 0>, 0.06 }
    texture { T_Brass_4C }
  }
  cone {
    <0, 0.35, 0>, 0.25, <0, 0.6, 0>, 0.14
    pigment { color rgbf <0.95, 0.85, 0.6, 0.4> }
    finish { ambient 0.6 diffuse 0.5 }
  }
  translate <-1.6, 0.74, 0.7>
}

// cup on the table
union {
  cylinder { <0, 0, 0>, <0, 0.1, 0>, 0.045 }
  torus { 0.03, 0.008 rotate x*90 translate <0.055, 0.05, 0> }
  texture { pigment { White } finish { phong 0.9 reflection 0.1 } }
  translate <-1.35, 0.74, 0.45>
}

// ---------------------------------------------------------------
// Rug with radial and onion patterns
// ---------------------------------------------------------------
cylinder {
  <0, 0, 0>, <0, 0.015, 0>, 1.2
  texture {
    pigment {
      onion
      pigment_map {
        [0.0 color rgb <0.5, 0.08, 0.06>]
        [0.3 radial frequency 12 color_map { [0.5 color rgb <0.75, 0.6, 0.3>] [0.5 color rgb <0.2, 0.15, 0.35>] }]
        [0.7 color rgb <0.5, 0.08, 0.06>]
        [1.0 color rgb <0.2, 0.15, 0.35>]
      }
      scale 0.6
    }
    normal { bumps 0.2 scale 0.01 }
    finish { diffuse 0.8 ambient 0.05 }
  }
  scale <1.2, 1, 0.8>
  translate <-0.2, 0, 0.2>
}

// a toy ball on the rug
sphere {
  <0.5, 0.2, -0.3>, 0.2
  texture {
    pigment { Candy_Cane scale 0.1 }
    finish { phong 0.8 ambient 0.1 }
  }
}

// potted plant in the corner of the window
union {
  cone { <0, 0, 0>, 0.16, <0, 0.35, 0>, 0.22 texture { T_Stone25 scale 0.2 } }
  #for (Lf, 0, 8)
    sphere {
      0, 1 scale <0.06, 0.3, 0.12>
      rotate <25 + 10 * mod(Lf, 3), Lf * 40, 0>
      translate <0, 0.5, 0>
      pigment { color rgb <0.1, 0.45 + 0.05 * mod(Lf, 2), 0.12> }
      normal { wrinkles 0.4 scale 0.05 }
      finish { phong 0.4 }
    }
  #end
  translate <0.55, 0, 2.6>
}
