// A pattern's warps and turbulence move the point its map's or list's entries are evaluated
// at (pigment_map, pigment list, texture_map, normal_map), while marble's own turbulence,
// not a warp, leaves them alone (render::pattern::warped; advanced/biscuit, wallstucco).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at <0, 0, 0> angle 50 }
light_source { <-10, 6, -8> color 1 }
#declare S = pigment { gradient y color_map { [0.5 rgb <0.1,0.2,0.6>] [0.5 rgb 1] } scale 0.3 };
#declare T = texture { pigment { S } finish { phong 0.5 } };
sphere { <-1.1, 1.1, 0>, 1 pigment { gradient x pigment_map { [0 S] [1 S] } warp { turbulence 0.4 } } }
sphere { <1.1, 1.1, 0>, 1 pigment { checker pigment { S } pigment { S rotate 90*z } scale 0.7 turbulence 0.5 } }
sphere { <-1.1, -1.1, 0>, 1 texture { marble texture_map { [0 T] [1 T] } turbulence 0.6 } }
sphere { <1.1, -1.1, 0>, 1 pigment { rgb 1 } normal { gradient x normal_map { [0 gradient y 1 scale 0.3] [1 gradient y 1 scale 0.3] } warp { turbulence 0.4 } } }
