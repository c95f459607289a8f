#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-10> look_at 0 angle 26 }
light_source { <-5,8,-10> rgb 1 }
#declare F = finish { ambient 0.4 diffuse 0.6 }
box { <-2.2,0.05,0>, <-0.05,1.7,1> pigment { mandel 30 exponent 3 scale 0.8 translate <-1.1,0.9,0> } finish { F } }
box { <0.05,0.05,0>, <2.2,1.7,1> pigment { julia <0.353,0.288>, 30 interior 1, 1 color_map { [0 rgb 0][0.2 rgb x][0.4 rgb x+y][1 rgb 1][1 rgb 0] } scale 0.6 translate <1.1,0.9,0> } finish { F } }
box { <-2.2,-1.7,0>, <-0.05,-0.05,1> pigment { mandel 30 exterior 3, 0.2 interior 2, 0.5 color_map { [0 rgb <0,0,0.4>][1 rgb <1,0.8,0.2>] } scale 0.7 translate <-0.9,-0.9,0> } finish { F } }
sphere { <1.1,-0.9,0>, 0.85 pigment { julia <0.4,0.3>, 40 exponent 5 exterior 7, 5 scale 0.7 translate <1.1,-0.9,0> } finish { F } }
