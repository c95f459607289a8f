// metallic highlights and reflection fade from the pigment's colour head-on to the light's at
// glancing angles: tint 1 + metallic·(1 − k(θ))·(c − 1), θ the angle of the light (highlights)
// or of the ray (reflection) to the normal, k measured by scripts/measure_metallic.py
// (render::metallic).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -6> look_at <0, 0, 0> angle 45 }
light_source { <3, 4, -6> color 1 }
light_source { <-8, 1, 3> color rgb <0.8, 0.9, 1> }
sky_sphere { pigment { gradient y color_map { [0 rgb 1] [1 rgb <0.4, 0.6, 1>] } } }
sphere { <-1.1, 0, 0>, 1 pigment { rgb <1, 0.3, 0.05> } finish { ambient 0 diffuse 0.2 reflection { 0.9 metallic } } }
sphere { <1.1, 0, 0>, 1 pigment { rgb <0.9, 0.7, 0.1> } finish { ambient 0 diffuse 0.3 phong 1 phong_size 5 specular 0.6 roughness 0.1 metallic 0.7 } }
