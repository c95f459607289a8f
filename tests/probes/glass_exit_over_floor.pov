#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5.5> look_at <0, 1.0, 0> angle 48 right x*image_width/image_height }
light_source { <-8, 12, -6> color rgb <1, 0.97, 0.9> }
plane { y, 0 pigment { checker color rgb <0.90, 0.88, 0.80> color rgb <0.55, 0.12, 0.10> } finish { ambient 0.06 diffuse 0.8 } }
sphere { <0, 1.0, 0>, 1.0 pigment { color rgbf <0.97, 1.0, 0.98, 0.95> }
  finish { ambient 0 diffuse 0 reflection { 0.0, 1.0 fresnel on } conserve_energy }
  interior { ior 1.474 } }
