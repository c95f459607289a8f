// POV-Ray's noise_generator 3, measured from the binary (render::noise, noise3_data,
// scripts/measure_noise3.py): bozo, granite and agate pigments, dents and wrinkles normals,
// and the scene-wide generator reaching a pattern that names none.
#version 3.7;
global_settings { assumed_gamma 1.0 noise_generator 3 }
camera { location <0, 0, -6> look_at <0, 0, 0> angle 50 }
light_source { <-10, 6, -4> color 1 }
#declare F = finish { ambient 0.1 diffuse 0.8 phong 0.5 phong_size 30 };
sphere { <-1.6, 1.1, 0>, 0.75 pigment { bozo scale 0.3 color_map { [0 rgb <1,0.2,0>] [1 rgb <0,0.3,1>] } } finish { F } }
sphere { <0, 1.1, 0>, 0.75 pigment { granite scale 1.5 noise_generator 3 color_map { [0 rgb 1] [1 rgb 0] } } finish { F } }
sphere { <1.6, 1.1, 0>, 0.75 pigment { agate agate_turb 0.7 scale 0.7 noise_generator 3 } finish { F } }
sphere { <-1.6, -1.1, 0>, 0.75 pigment { rgb 1 } finish { F } normal { dents 3 scale 0.25 noise_generator 3 } }
sphere { <0, -1.1, 0>, 0.75 pigment { rgb 1 } finish { F } normal { wrinkles 0.8 scale 0.4 noise_generator 3 } }
sphere { <1.6, -1.1, 0>, 0.75 pigment { marble turbulence 0.8 octaves 4 noise_generator 3 color_map { [0 rgb <0.2,0.8,0.3>] [1 rgb 1] } } finish { F } }
