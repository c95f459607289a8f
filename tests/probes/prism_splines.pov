// Prism outlines in all four spline kinds, with holes from nested sub-outlines (linear sweep, caps).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.3,7,-6.2> look_at <0,0.2,0.1> angle 50 }
light_source { <-5,9,-6> rgb 1 }
light_source { <6,5,-3> rgb 0.3 }
plane { y, -0.01 pigment { rgb 0.7 } }
#declare F = finish { phong 0.5 }
prism { linear_spline 0, 0.9, 10, <0,0>, <2.1,0>, <2.1,1.7>, <0,1.7>, <0,0>, <0.5,0.45>, <1.55,0.45>, <1.55,1.3>, <0.5,1.3>, <0.5,0.45>
  translate <-3.1,0,0.35> pigment { rgb <1,0.5,0.2> } finish { F } }
prism { quadratic_spline 0, 0.7, 12, <1,-1>, <0,0>, <6,0>, <6,8>, <0,8>, <0,0>, <2,0>, <1,1>, <5,1>, <5,7>, <1,7>, <1,1>
  scale <0.27,1,0.22> translate <0.37,0,0.31> pigment { rgb <0.3,0.8,0.3> } finish { F } }
prism { cubic_spline 0, 1.1, 14, <1,-1>, <0,0>, <6,0>, <6,8>, <0,8>, <0,0>, <-1,1>, <2,0>, <1,1>, <5,1>, <5,7>, <1,7>, <1,1>, <0,2>
  scale <0.3,1,0.22> translate <-2.93,0,-2.21> rotate y*7 pigment { rgb <0.4,0.5,1> } finish { F } }
prism { bezier_spline 0.2, 0.8, 16, <0,0>, <1,-1.5>, <3,-1>, <3,0>, <3,0>, <3,1.5>, <2,3>, <1.5,2.2>, <1.5,2.2>, <1,1.5>, <-1,3>, <-1.5,1.5>, <-1.5,1.5>, <-2,0>, <-1,1>, <0,0>
  scale 0.55 rotate y*23 translate <1.63,0,-1.57> pigment { rgb <1,0.8,0.3> } finish { F } }
