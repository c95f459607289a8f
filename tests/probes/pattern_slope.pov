// slope and aoi: angle-linear values of the viewer-facing, perturbed world normal; slope's
// direction and point_at in world space, altitude in pattern space, lo/hi unclipped (wrapped);
// a slope texture_map. Measured with scripts/measure_slope.py (docs/povray-behaviour.md).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-10> look_at 0 angle 26 }
light_source { <-5,8,-10> rgb 1 }
#declare F = finish { ambient 0.5 diffuse 0.5 }
sphere { <-1.1,0.9,0>, 0.8 pigment { slope { y*2, 0.2, 0.6 altitude x, 0.5, -0.5 } color_map { [0 rgb <0,0,0.4>][1 rgb <1,0.9,0.6>] } translate -1.1*x } finish { F } }
sphere { <1.1,0.9,0>, 0.8 pigment { aoi color_map { [0.5 rgb 0][1 rgb <1,0.5,0>] } } normal { bumps 0.6 scale 0.2 } finish { F } }
sphere { <-1.1,-0.9,0>, 0.8 pigment { slope { point_at <0,3,-2> } color_map { [0 rgb 0][1 rgb <0.3,1,0.5>] } rotate 40*z } finish { F } }
sphere { <1.1,-0.9,0>, 0.8 texture { slope { -y, 0, 0.5 altitude y, -1.7, -0.1 } texture_map { [0.4 pigment { rgb <0.2,0.6,0.1> } finish { F } ][0.6 pigment { rgb 0.5 } normal { bumps 0.5 scale 0.1 } finish { F } ] } } }
