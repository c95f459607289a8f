#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-10> look_at 0 angle 26 }
light_source { <-5,8,-10> rgb 1 }
#declare F = finish { ambient 0.4 diffuse 0.6 }
box { <-2.2,0.05,0>, <-0.05,1.7,1> pigment { planar pigment_map { [0 checker rgb 0, rgb 1 scale 0.2][1 rgb <1,0.3,0>] } scale 0.8 translate y*0.9 } finish { F } }
box { <0.05,0.05,0>, <2.2,1.7,1> pigment { spiral1 3 color_map { [0 rgb <0,0,0.4>][1 rgb <1,0.9,0.6>] } translate <1.1,0.9,0> } finish { F } }
box { <-2.2,-1.7,0>, <-0.05,-0.05,1> pigment { function { abs(sin(x*4)*cos(y*4)) } color_map { [0 rgb 0][1 rgb <0.8,0.4,1>] } } finish { F } }
sphere { <1.1,-0.9,0>, 0.85 pigment { gradient y pigment_map { [0.2 rgb <0,0.3,0>][0.5 wood scale 0.1][0.8 radial frequency 8] } scale 2 translate -y*1.9 } finish { F } }
