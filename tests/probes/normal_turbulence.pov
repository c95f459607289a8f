// A normal pattern under turbulence or a warp takes its slope samples around the point the
// warp moved once (render::normal::slope), not by warping each sample: measured with mirrors
// whose crackle, bozo and granite normals carry turbulence, reflecting a sky coloured by
// direction (exact to the 16-bit step against povray).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -3> look_at <0, 0.2, 0> angle 60 }
sky_sphere { pigment { gradient x color_map { [0 rgb <1, 0, 0>] [0.5 rgb <0, 1, 0>] [1 rgb <0, 0, 1>] } scale 0.5 } }
#declare M = finish { ambient 0 diffuse 0 reflection 1 }
box { <-3, -1, -3>, <-0.7, 0, 5> pigment { rgb 0 } finish { M } normal { crackle 0.15 scale <0.35, 0.25, 0.25> turbulence 0.5 } }
box { <-0.7, -1, -3>, <0.7, 0, 5> pigment { rgb 0 } finish { M } normal { bozo 0.15 warp { turbulence 0.5 } scale <0.35, 0.25, 0.25> } }
box { <0.7, -1, -3>, <3, 0, 5> pigment { rgb 0 } finish { M } normal { granite 0.3 turbulence 0.3 scale 0.5 } }
