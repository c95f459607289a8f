// double_illuminate: a light behind the surface lights it as if from the front (diffuse
// only, no phong or specular), measured with povray on a plane lit from behind.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> look_at 0 }
light_source { <2, 1, 5> rgb 1 }
light_source { <-3, 2, -5> rgb 0.3 }
plane { z, 0 pigment { rgb 0.8 } finish { ambient 0.1 diffuse 0.6 phong 1 specular 0.5 } double_illuminate }
sphere { <1, 0, -1>, 0.5 pigment { rgb <1, 0.5, 0> } finish { phong 1 } double_illuminate }
