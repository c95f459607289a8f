// Ripples and waves, as normals and as pigments, from POV-Ray's ten measured wave sources
// (render::pattern::WAVE_SOURCES, render::normal), with frequency and phase.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at <0, 0, 0> angle 50 }
light_source { <-10, 6, -4> color 1 }
#declare F = finish { ambient 0.05 diffuse 0.8 phong 0.6 phong_size 30 };
sphere { <-1.1, 1.1, 0>, 1 pigment { rgb 1 } finish { F } normal { ripples 0.8 scale 0.5 } }
sphere { <1.1, 1.1, 0>, 1 pigment { rgb 1 } finish { F } normal { waves 0.6 frequency 2 phase 0.3 scale 0.7 } }
sphere { <-1.1, -1.1, 0>, 1 pigment { ripples frequency 1.5 phase 0.2 scale 0.4 } finish { F } }
sphere { <1.1, -1.1, 0>, 1 pigment { waves scale 0.3 color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] } } finish { F } normal { ripples 0.3 frequency 3 } }
