#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,4,-9> look_at <0,0.5,0> angle 50 }
light_source { <-5,8,-6> rgb 1 }
light_source { <6,3,-4> rgb 0.3 }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.4 } }
box { <-3.5,-1,-0.5>, <-2.5,0,0.5> rotate y*30 pigment { rgb <0.9,0.3,0.2> } finish { phong 0.6 } }
cylinder { <-1.5,-1,0>, <-1,1,0.5>, 0.4 pigment { rgb <0.2,0.8,0.3> } finish { specular 0.5 roughness 0.02 } }
cylinder { <0,-1,1.5>, <0,0.5,1.5>, 0.5 open pigment { rgb <0.9,0.9,0.2> } }
cone { <0.5,-1,0>, 0.7, <1,1,0>, 0.1 pigment { rgb <0.2,0.4,0.9> } finish { phong 0.5 } }
cone { <-0.5,0.5,-1.5>, 0.0, <-0.5,-1,-1.5>, 0.5 open pigment { rgb <0.8,0.5,0.9> } }
disc { <2.2,0,-1>, <0,1,-1>, 0.7, 0.3 pigment { rgb <0.9,0.6,0.2> } }
torus { 0.6, 0.2 rotate x*60 translate <3,0.2,1> pigment { rgb <0.3,0.9,0.9> } finish { phong 0.8 } sturm }
smooth_triangle { <-3,1.2,1>, <-0.4,0.2,-1>, <-1,1.4,1>, <0.4,0.3,-1>, <-2,2.6,1.5>, <0,0.8,-1> pigment { rgb <1,0.7,0.7> } }
triangle { <1,1.5,2>, <3,1.5,2>, <2,2.8,2.5> pigment { rgb <0.7,0.7,1> } }
