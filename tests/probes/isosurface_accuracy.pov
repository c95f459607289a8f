// Isosurface hit points and normals: povray reports the far end of the last accuracy-sized piece and takes forward differences one accuracy long (accuracy 0.02 makes both visible).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,5,-5> look_at 0 right x*2.4 up y*1.8 }
light_source { <4,8,-6> rgb 1 }
background { rgb <0.2,0.3,0.5> }
isosurface { function { y - 0.06*sin(20*x)*sin(20*z) } accuracy 0.02 max_gradient 2
  contained_by { box { <-1,-0.5,-1>, <1,0.5,1> } } open
  pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
