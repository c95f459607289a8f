#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,3,-8> look_at <0,0.3,0> angle 50 }
light_source { <-5,8,-6> rgb 1 }
plane { y, -1 pigment { rgb 0.7 } }
intersection { sphere { 0, 1 } box { -0.7, 0.7 } translate x*-2.5 pigment { rgb <0.9,0.3,0.2> } finish { phong 0.5 } }
difference { box { -0.8, 0.8 } sphere { <0,0.4,-0.4>, 0.7 } cylinder { -2*x, 2*x, 0.3 } rotate y*20 pigment { rgb <0.2,0.8,0.3> } }
merge { sphere { 0, 0.7 } sphere { x*0.6, 0.6 } translate <2.3,0,0> pigment { rgbf <0.6,0.8,1,0.8> } interior { ior 1.3 } }
union { sphere { <0,0,2>, 0.5 } box { <-0.3,-1,1.7>, <0.3,2,2.3> } pigment { rgb <1,0.9,0.3> } rotate y*-30 }
sphere { <0,1.8,0>, 0.4 inverse pigment { rgb 1 } }
difference { sphere { 0, 0.6 } plane { y, 0 } translate <-1,1.5,-1> pigment { rgb <0.8,0.4,0.9> } }
