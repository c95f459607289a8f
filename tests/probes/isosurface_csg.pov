// Isosurfaces: scaled with a closed sphere container, in a CSG difference (all_intersections), threshold with evaluate; shadows on a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0,3,-8> look_at 0 angle 50 }
light_source { <4,8,-6> rgb 1 }
background { rgb <0.2,0.3,0.5> }
plane { y, -1.2 pigment { checker rgb 1 rgb 0.3 } }
// scaled, sphere container, closed walls
isosurface { function { x*x + z*z - 0.3 + 0.2*sin(3*y) } contained_by { sphere { 0, 1 } } max_gradient 3
  pigment { rgb <1,0.5,0.2> } finish { phong 0.5 } scale <1.2,0.8,1> translate <-2.5,0,0> }
// difference with all_intersections
difference {
  isosurface { function { y - 0.3*sin(4*x) } contained_by { box { <-1,-1,-1>, <1,0.8,1> } } all_intersections max_gradient 2 }
  sphere { <0,0.3,-1>, 0.6 }
  pigment { rgb <0.3,0.8,0.3> } translate <2.5,0,0> }
// threshold and evaluate
isosurface { function { sqrt(x*x+y*y+z*z) + 0.3*sin(6*x) } threshold 0.8 evaluate 1, 1.5, 0.7 contained_by { box { -1.5, 1.5 } }
  pigment { rgb <0.5,0.5,1> } scale 0.7 translate <0,0,3.5> }
