#version 3.7;
global_settings { assumed_gamma 2.2 }
camera { location <0,0,-3> look_at 0 angle 50 }
light_source { <-3,4,-5> rgb 1 }
box { <-1.5,-1,0>, <1.5,1,0.1> pigment { image_map { png "../../scenes/sky.png" } scale <3,2,1> translate <-1.5,-1,0> } finish { ambient 0.3 diffuse 0.7 } }
sphere { <1,0.5,-0.5>, 0.4 pigment { image_map { png "../../scenes/sky.png" map_type 1 } } finish { ambient 1 diffuse 0 } }
