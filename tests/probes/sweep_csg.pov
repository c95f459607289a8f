// CSG with prism, lathe, sor and sphere_sweep: their inside tests decide which crossings survive.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.4,4.2,-6.8> look_at <0,0.7,0> angle 50 }
light_source { <-5,9,-6> rgb 1 }
light_source { <6,5,-3> rgb 0.3 }
plane { y, -0.01 pigment { rgb 0.7 } }
#declare F = finish { phong 0.5 }
difference {
  lathe { cubic_spline 8, <0.3,1.5>, <0.5,0>, <2,0.5>, <1.5,2.5>, <1,3>, <0.3,1.5>, <0.5,0>, <2,0.5> }
  prism { -1, 4, 4, <-3,-0.31>, <3,-0.33>, <3,0.29>, <-3,-0.31> }
  sphere_sweep { linear_spline 2, <-3,1.5,-1>,0.5 <3,1.5,-1>,0.5 }
  scale 0.7 translate x*-1.6 pigment { rgb <1,0.7,0.5> } finish { F } }
intersection {
  sor { 5, <0,-1>, <1,0>, <1.3,1.2>, <0.9,2.2>, <0.5,3> }
  prism { cubic_spline -1, 4, 8, <0,-1.2>, <1.2,0>, <0,1.2>, <-1.2,0>, <0,-1.2>, <1.2,0>, <0,1.2>, <-1.2,0> scale <1.4,1,0.8> }
  scale 0.8 rotate y*20 translate x*1.7 pigment { rgb <0.5,0.7,1> } finish { F } }
