#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-10> look_at 0 angle 26 }
light_source { <-5,8,-10> rgb 1 }
#declare F = finish { ambient 0.4 diffuse 0.6 }
box { <-2.2,0.05,0>, <-0.05,1.7,1> pigment { radial frequency 5 rotate x*90 } finish { F } }
box { <0.05,0.05,0>, <2.2,1.7,1> pigment { onion color_map { [0 rgb <1,1,0>][0.5 rgb <0,0.5,1>][1 rgb 0] } scale 0.5 translate <1,0.9,0> } finish { F } }
box { <-2.2,-1.7,0>, <-0.05,-0.05,1> pigment { spherical color_map { [0 rgb 0][1 rgb <1,0.5,0.2>] } scale 0.9 translate <-1.1,-0.9,0> } finish { F } }
sphere { <1.1,-0.9,0>, 0.85 pigment { cylindrical scale 0.6 rotate z*30 translate <1.1,-0.9,-0.5> } finish { F } }
