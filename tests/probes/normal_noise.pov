// Bumps, dents and wrinkles on POV-Ray's exact noise (render::noise, render::normal): bumps
// n + amount·DNoise, dents n + amount·noise³·DNoise, wrinkles ten octaves of |DNoise|
// halving; generators 1 and 2, scale, turbulence (scripts/measure_normals.py).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at <0, 0, 0> angle 50 }
light_source { <-10, 6, -4> color 1 }
#declare F = finish { ambient 0.05 diffuse 0.8 phong 0.6 phong_size 30 };
sphere { <-1.1, 1.1, 0>, 1 pigment { rgb 1 } finish { F } normal { bumps 0.8 scale 0.3 } }
sphere { <1.1, 1.1, 0>, 1 pigment { rgb 1 } finish { F } normal { dents 1.5 scale 0.25 noise_generator 1 } }
sphere { <-1.1, -1.1, 0>, 1 pigment { rgb 1 } finish { F } normal { wrinkles 0.7 scale 0.4 } }
sphere { <1.1, -1.1, 0>, 1 pigment { rgb <1,0.8,0.6> } finish { F } normal { bumps 0.5 scale 0.3 turbulence 0.5 noise_generator 1 } }
