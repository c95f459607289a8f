#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-10> look_at 0 angle 26 }
light_source { <-5,8,-10> rgb 1 }
#declare F = finish { ambient 0.4 diffuse 0.6 }
box { <-2.2,0.05,0>, <-0.05,1.7,1> pigment { checker rgb <1,0.8,0.2>, rgb <0.1,0.2,0.6> scale 0.4 } finish { F } }
box { <0.05,0.05,0>, <2.2,1.7,1> pigment { hexagon pigment { rgb 1 }, pigment { gradient y color_map { [0 rgb <1,0,0>][1 rgb <0,0,1>] } scale 0.3 }, pigment { rgb <0.2,0.6,0.2> } rotate x*90 scale 0.3 } finish { F } }
box { <-2.2,-1.7,0>, <-0.05,-0.05,1> pigment { brick scale 0.06 } finish { F } }
sphere { <1.1,-0.9,0>, 0.85 pigment { hexagon scale 0.25 rotate <90,20,0> } finish { F } }
