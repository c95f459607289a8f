// The object pattern: the second list item inside the object, the first outside; a text
// object, a CSG and a plain sphere, with colours, pigments and the default items.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -5> look_at 0 right x*8 up y*6 }
#declare Letter = text { internal 1 "X" 1, 0 scale 1.5 translate <-0.5, -0.5, -0.5> }
plane { z, 0 finish { ambient 1 diffuse 0 }
  pigment { object { Letter pigment { rgb <0.2, 0.3, 0.9> } pigment { gradient x color_map { [0 rgb 1] [1 rgb <1, 0.5, 0>] } } } translate <-2.5, 1.2, 0> } }
plane { z, -0.01 finish { ambient 1 diffuse 0 } clipped_by { box { <-0.9, -3, -1>, <4, 3, 1> } }
  pigment { object { difference { sphere { 0, 1 } box { 0, 2 } } color rgbt <0, 0, 0, 1> color rgb <0.9, 0.1, 0.1> } translate <2, 1.3, 0> } }
plane { z, -0.02 finish { ambient 1 diffuse 0 } clipped_by { box { <-4, -3, -1>, <4, -0.2, 1> } }
  pigment { object { sphere { <0, -1.6, 0>, 1 } } } }
