// Prism conic_sweep (linear and cubic outlines, a truncated pyramid upside down) and an open prism seen inside.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.2,4.3,-7.1> look_at <0,0.6,0> angle 48 }
light_source { <-5,9,-6> rgb 1 }
light_source { <6,5,-3> rgb 0.3 }
plane { y, -1.01 pigment { rgb 0.7 } }
#declare F = finish { phong 0.5 }
prism { conic_sweep linear_spline 0.43, 1, 5, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1>
  rotate x*180 translate y*1 scale <1.3,2.1,1.3> rotate y*25 translate <-2.6,-1,0> pigment { rgb <0.9,0.3,0.3> } finish { F } }
prism { conic_sweep cubic_spline 0.21, 1, 8, <0,-1.2>, <1.2,0>, <0,1.2>, <-1.2,0>, <0,-1.2>, <1.2,0>, <0,1.2>, <-1.2,0>
  scale <1.1,2.4,1.1> translate <0.07,-1,0.3> pigment { rgb <0.8,0.4,0.9> } finish { F } }
prism { linear_spline -1, 0.53, 5, <-0.9,-0.6>, <0.9,-0.73>, <0.7,0.84>, <-0.77,0.71>, <-0.9,-0.6> open
  rotate y*10 translate <2.6,0,0> pigment { rgb <0.2,0.8,0.8> } finish { F } }
