// Area light, adaptive 1: soft shadows from a 5x5 array.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,6,-8> look_at <0,0,0> angle 50 }
light_source { <1,8,-2> rgb 1 area_light x*2, z*2, 5, 5 adaptive 1 }
plane { y, 0 pigment { checker rgb 1 rgb 0.6 } }
sphere { <0,1,0>, 1 pigment { rgb <1,0.3,0.2> } finish { phong 0.5 } }
box { <-3,0,1>, <-2,2,2> pigment { rgb <0.3,0.5,1> } }
