#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-10> look_at 0 angle 26 }
light_source { <-5,8,-10> rgb 1 }
#declare F = finish { ambient 0.4 diffuse 0.6 }
#declare P = function { pigment { checker rgb <1,0.5,0.2>, rgb <0.1,0.2,0.9> scale 0.3 } }
#declare W = function { pattern { wood scale 0.2 } }
box { <-2.2,0.05,0>, <-0.05,1.7,1> pigment { function { P(x,y,z).gray * W(x,y,z) } color_map { [0 rgb 0][1 rgb <1,0.8,0.3>] } } finish { F } }
box { <0.05,0.05,0>, <2.2,1.7,1> pigment { pigment_pattern { radial frequency 4 rotate x*90 } color_map { [0 rgb <0,0.2,0>][1 rgb <1,1,0.5>] } } finish { F } }
box { <-2.2,-1.7,0>, <-0.05,-0.05,1> pigment { julia <0.353,0.288>, 40 scale 0.8 translate <-1.1,-0.9,0> color_map { [0 rgb 0][0.2 rgb <1,0.3,0>][1 rgb 1] } } finish { F } }
sphere { <1.1,-0.9,0>, 0.85 pigment { average pigment_map { [1 gradient x color_map { [0 rgb 0][1 rgb <1,0,0>] }] [2 onion scale 0.3 color_map { [0 rgb <0,0,1>][1 rgb 1] }] } } finish { F } }
