// Tilted ground fog (density 1/(1+x^2) above the offset) under a constant fog: layers add colours.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,2,-8> look_at <0,1,0> angle 60 }
light_source { <3,8,-4> rgb 1 }
background { rgb <0.1,0.2,0.6> }
plane { y, 0 pigment { checker rgb 1 rgb 0.4 } finish { reflection 0.2 } }
sphere { <0,1,0>, 1 pigment { rgb <1,0.3,0.2> } }
sphere { <3,1,8>, 1 pigment { rgb <0.2,1,0.2> } }
sphere { <-4,1,20>, 1 pigment { rgb <0.2,0.2,1> } }
fog { fog_type 2 distance 5 color rgb <1,0.9,0.8> fog_offset 1 fog_alt 0.5 up <0.3,1,0> } fog { distance 30 color rgb <0.2,0.3,0.5> }
