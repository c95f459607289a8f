#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-10> look_at 0 angle 26 }
light_source { <-5,8,-10> rgb 1 }
#declare F = finish { ambient 0.4 diffuse 0.6 }
box { <-2.2,0.05,0>, <-0.05,1.7,1> pigment { wood scale 0.15 } finish { F } }
box { <0.05,0.05,0>, <2.2,1.7,1> pigment { marble scale 0.5 } finish { F } }
box { <-2.2,-1.7,0>, <-0.05,-0.05,1> pigment { leopard scale 0.12 color_map { [0 rgb 1][0.5 rgb <1,0.5,0>][1 rgb 0] } } finish { F } }
sphere { <1.1,-0.9,0>, 0.85 pigment { boxed cubic_wave color_map { [0 rgb 0][1 rgb <0.2,0.8,1>] } scale 0.7 translate <1.1,-0.9,0> } finish { F } }
