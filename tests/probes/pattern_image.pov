#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-10> look_at 0 angle 26 }
light_source { <-5,8,-10> rgb 1 }
#declare F = finish { ambient 0.4 diffuse 0.6 }
box { <-2.2,-1.7,0>, <-0.05,1.7,1> pigment { image_pattern { png "pattern_image.png" } color_map { [0 rgb <0,0,0.3>][1 rgb <1,0.9,0.5>] } scale <2.15,3.4,1> translate <-2.2,-1.7,0> } finish { F } }
box { <0.05,-1.7,0>, <2.2,1.7,1> pigment { image_pattern { png "pattern_image.png" interpolate 2 use_alpha } color_map { [0 rgb <1,0,0>][1 rgb 1] } scale <2.15,3.4,1> translate <0.05,-1.7,0> } finish { F } }
