// Orthographic camera with an angle: the perspective view's area at the look_at point.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-5> look_at <0,0,3> right x*4 up y*3 angle 40 }
light_source { <3,4,-5> rgb 1 }
#for (i,-3,3) #for (j,-2,2) sphere { <i,j,0>, 0.15 pigment { rgb <1,0.5,0.2> } } #end #end
sphere { <1,1,6>, 1 pigment { rgb <0.2,0.5,1> } }
plane { z, 8 pigment { checker rgb 1 rgb 0.3 } }
