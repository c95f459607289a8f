// Constant fog with transmit: at least that share of what is behind shows.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,2,-8> look_at <0,1,0> angle 60 }
light_source { <3,8,-4> rgb 1 }
background { rgb <0.1,0.2,0.6> }
plane { y, 0 pigment { checker rgb 1 rgb 0.4 } finish { reflection 0.2 } }
sphere { <0,1,0>, 1 pigment { rgb <1,0.3,0.2> } }
sphere { <3,1,8>, 1 pigment { rgb <0.2,1,0.2> } }
sphere { <-4,1,20>, 1 pigment { rgb <0.2,0.2,1> } }
fog { distance 8 color rgbt <0.8,0.7,0.6,0.3> }
