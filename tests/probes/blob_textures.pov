// Blob component textures: weighted by |field|, untextured components bring the blob's texture, shares under adc_bailout dropped.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-10> look_at 0 right x*4 up y*3 }
blob { threshold 0.1
  sphere { <-0.6,0,0>, 1.5, 1 pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } }
  sphere { <0.6,0,0>, 1.5, 0.5 }
  sphere { <0,0,-1>, 0.6, -0.3 pigment { rgb <0,0,1> } finish { ambient 1 diffuse 0 } }
  finish { ambient 1 diffuse 0 } pigment { rgb <0,1,0> }
}
