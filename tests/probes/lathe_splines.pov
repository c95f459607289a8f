// Lathe profiles in linear, quadratic, cubic and Bezier splines, one an open (unclosed) profile.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.1,6.3,-7.4> look_at <0,0.9,0> angle 50 }
light_source { <-5,9,-6> rgb 1 }
light_source { <6,5,-3> rgb 0.3 }
plane { y, -0.01 pigment { rgb 0.7 } }
#declare F = finish { phong 0.5 }
lathe { linear_spline 6, <0.5,0>, <2,0.3>, <1.7,1.8>, <1,2.4>, <0.3,1.4>, <0.5,0> scale 0.61 translate <-2.4,0,1.3> pigment { rgb <1,0.6,0.3> } finish { F } }
lathe { quadratic_spline 7, <0.3,1.5>, <0.5,0>, <2,0.5>, <1.5,2.5>, <1,3>, <0.3,1.5>, <0.5,0> scale 0.53 translate <1.1,0,1.7> pigment { rgb <0.5,1,0.4> } finish { F } }
lathe { cubic_spline 8, <0.3,1.5>, <0.5,0>, <2,0.5>, <1.5,2.5>, <1,3>, <0.3,1.5>, <0.5,0>, <2,0.5> scale 0.57 translate <-1.3,0,-1.6> pigment { rgb <0.5,0.6,1> } finish { F } }
lathe { bezier_spline 8, <0.5,0>, <2,-0.5>, <2.2,1.5>, <1.5,2.5>, <1.5,2.5>, <1,3.5>, <0.25,0.5>, <0.5,0> scale 0.55 translate <1.9,0,-1.1> pigment { rgb <1,0.9,0.4> } finish { F } }
lathe { cubic_spline 6, <0,-0.5>, <1.8,0>, <1.6,1>, <0.7,1.8>, <1.2,2.8>, <1.5,3.5> scale 0.4 translate <3.7,0,1.9> pigment { rgb <0.9,0.5,0.5> } finish { F } }
