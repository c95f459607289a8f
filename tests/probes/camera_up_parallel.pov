// Camera with up z and the default direction z (handedness test gives zero): POV-Ray renders it mirrored.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <-10, 10, -10> right x*4/3 up z look_at <0, 0, 0> angle 20 }
light_source { <-5,9,-6> rgb 1 }
plane { y, -0.01 pigment { rgb 0.7 } }
box { <-1,0,-1>, <0.3,1,0.3> translate x*1.1 pigment { rgb <1,0.4,0.2> } }
sphere { <-0.9,0.5,0.6>, 0.5 pigment { rgb <0.3,0.5,1> } }
