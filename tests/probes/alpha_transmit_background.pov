// options: +UA
// Output_Alpha: the background's transmit goes to the alpha channel along straight rays
// (through transmit and filter panes, two faces each), while the mirror sees its full colour.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-5> look_at <0,0,0> right x*4 up y*3 }
background { color rgbt <0.2,0.3,0.5,0.5> }
box { <-2,-1,0>, <-1,1,0.1> pigment { rgb <1,0,0> } finish { ambient 0 diffuse 0 reflection 1 } rotate y*30 }
box { <-0.5,-1.5,0>, <0.5,1.5,0.1> pigment { rgbt <1,1,0,0.5> } finish { ambient 1 diffuse 0 } }
box { <1,-1.2,0>, <2,1.2,0.1> pigment { rgbf <1,1,0,0.5> } finish { ambient 1 diffuse 0 } }
sphere { <1.5,0,-1>, 0.4 pigment { rgb <0,1,0> } finish { ambient 1 diffuse 0 } }
