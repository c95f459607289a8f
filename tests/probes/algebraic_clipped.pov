// Algebraic surfaces (quartic torus with sturm, quadric and polynomial) and clipped_by.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"
camera { location <0,3,-8> look_at 0 angle 50 }
light_source { <4,8,-6> rgb 1 }
background { rgb <0.2,0.3,0.5> }
quartic {
  < 1,   0,   0,   0,   2,   0,   0,   2,   0,
  -104,   0,   0,   0,   0,   0,   0,   0,   0,
  0,   0,   1,   0,   0,   2,   0,  56,   0,
  0,   0,   0,   1,   0, -104,  0, 784 >
  sturm scale 0.3 translate x*-1.5
  pigment { rgb <1,0.5,0.2> } finish { phong 0.5 }
}
quadric { <1,0,1>, <0,0,0>, <0,-1,0>, 0 pigment { rgb <0.3,0.8,0.3> } clipped_by { box { -1, 1 } } translate <2,0,0> }
polynomial { 3, xyz(3,0,0):1, xyz(0,1,0):-1 pigment { rgb <0.3,0.3,1> } clipped_by { sphere { 0, 1.5 } } translate <0,0,3> }
