// ovus: bottom sphere, lemon and top sphere for several radius ratios (the lemon's profile
// radius is 2 max(bottom, top), measured), one in CSG, and one that is the top sphere alone.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,1,-10> look_at <0,0.6,0> angle 50 }
light_source { <4,8,-6> rgb 1 }
background { rgb <0.2,0.3,0.5> }
ovus { 1, 0.5 pigment { rgb <1,0.5,0.2> } finish { phong 0.6 } translate <-3,0.5,0> }
ovus { 1, 1 pigment { rgb <0.3,0.9,0.3> } rotate <0,0,30> translate <-0.6,0.3,0> }
ovus { 0.6, 0.9 pigment { rgb <0.4,0.4,1> } rotate <-30,0,0> translate <1.6,0.3,0> }
difference { ovus { 0.8, 0.6 } box { <0,-2,-2>, <2,3,0> } pigment { rgb 1 } rotate y*-40 translate <-1.6,-1.8,0> }
ovus { 0.3, 0.7 pigment { rgb <1,1,0> } translate <1.8,-2.2,0> }
