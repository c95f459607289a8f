#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-10> look_at 0 angle 26 }
light_source { <-5,8,-10> rgb 1 }
#declare F = finish { ambient 0.4 diffuse 0.6 }
box { <-2.2,0.05,0>, <-0.05,1.7,1> pigment { gradient x sine_wave frequency 2 color_map { [0 rgb 0][1 rgb <1,0.6,0.2>] } } finish { F } }
box { <0.05,0.05,0>, <2.2,1.7,1> pigment { gradient <1,1,0> scallop_wave phase 0.3 color_map { [0 rgb <0,0,0.5>][1 rgb 1] } } finish { F } }
box { <-2.2,-1.7,0>, <-0.05,-0.05,1> pigment { gradient y triangle_wave frequency 3 color_map { [0 rgb 0.1][0.5 rgb <0.9,0.2,0.1>][1 rgb 1] } } finish { F } }
sphere { <1.1,-0.9,0>, 0.85 pigment { gradient x poly_wave 2.5 frequency 1.5 phase 0.1 color_map { [0 rgb 0][1 rgb <0.3,1,0.3>] } } finish { F } }
