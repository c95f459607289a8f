// A height_field from a pigment function takes the pigment's grey as the height (it was flat
// in lancer: advanced/landscape.pov, advanced/wallstucco.pov).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5,2,-1.5> look_at <0.5,0,0.5> }
light_source { <2,5,-3> rgb 1 }
height_field { function 50,50 { pigment { gradient x color_map { [0 rgb <0,0.2,0.9>][1 rgb <1,0.5,0>] } } } pigment { rgb 1 } }
