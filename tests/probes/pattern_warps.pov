#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-10> look_at 0 angle 26 }
light_source { <-5,8,-10> rgb 1 }
#declare F = finish { ambient 0.4 diffuse 0.6 }
box { <-2.2,0.05,0>, <-0.05,1.7,1> pigment { gradient <1,1,0> color_map { [0 rgb <0,0,0.5>][1 rgb 1] } warp { repeat x*0.7 offset y*0.3 flip x } scale 0.8 } finish { F } }
box { <0.05,0.05,0>, <2.2,1.7,1> pigment { checker rgb 1, rgb <0.8,0.2,0> scale 0.15 warp { black_hole <1.1,0.9,0>, 0.7 falloff 1 strength 2 } } finish { F } }
box { <-2.2,-1.7,0>, <-0.05,-0.05,1> pigment { checker rgb 0.1, rgb <0.3,0.9,0.3> scale 0.2 warp { black_hole <0,0,0>, 0.5 repeat <2,1.5,0> strength 1.5 inverse } } finish { F } }
sphere { <1.1,-0.9,0>, 0.85 pigment { onion scale 0.3 warp { black_hole <0.5,0.5,0.5>, 0.4 repeat <1,1,1> falloff 3 } translate x*0.2 } finish { F } }
