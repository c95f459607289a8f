#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <1,0.8,0.8> }
#default { finish { ambient 0.3 diffuse 0.5 } }
camera { location <0,2,-6> look_at 0 right x*4/3 up y sky <0.2,1,0> }
light_source { <-3,5,-4> rgb 1 fade_distance 4 fade_power 2 }
background { rgb <0.2,0.25,0.3> }
plane { y, -1 pigment { gradient x color_map { [0 rgb <1,0,0>] [0.5 rgb <0,1,0>] [1 rgb <0,0,1>] } scale 2 rotate y*30 } }
sphere { 0, 1 pigment { checker rgb 1 rgb 0 scale 0.3 } scale <1.5,1,1> rotate z*30 translate x }
box { -0.5, 0.5 matrix <1,0.3,0, 0,1,0, 0,0,1, -2,0,0> pigment { rgb <0.3,0.6,0.9> } }
