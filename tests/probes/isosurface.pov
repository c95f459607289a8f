// Isosurfaces: default box container with a bumpy sphere, closed and open containers (box, sphere), threshold, accuracy.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,3,-8> look_at 0 angle 50 }
light_source { <4,8,-6> rgb 1 }
background { rgb <0.2,0.3,0.5> }
isosurface { function { sqrt(x*x+y*y+z*z) - 0.9 + 0.1*sin(8*x)*sin(8*y)*sin(8*z) } max_gradient 2
  pigment { rgb <1,0.5,0.2> } finish { phong 0.5 } translate <-2.5,0,0> }
isosurface { function { y + 0.2*sin(5*x) } contained_by { box { -1, 1 } } pigment { rgb <0.3,0.8,0.3> } rotate 20*y }
isosurface { function { y + 0.2*sin(5*x) } contained_by { sphere { 0, 1 } } open max_gradient 1.5 pigment { rgb <0.3,0.3,1> } finish { phong 0.8 } translate <2.5,0,0> }
isosurface { function { abs(x)+abs(y)+abs(z) - 1 } threshold 0.2 accuracy 0.0001 max_gradient 1.8 pigment { rgb 1 } translate <0,0,3> }
