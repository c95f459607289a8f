#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5.5> look_at <0, 1.0, 0> angle 48 right x*image_width/image_height }
plane { z, 3 pigment { checker color rgb <0.90, 0.88, 0.80> color rgb <0.55, 0.12, 0.10> } finish { ambient 1 diffuse 0 } }
sphere { <0, 1.0, 0>, 1.0 pigment { rgbf 1 }
  finish { ambient 0 diffuse 0 reflection { 0.0, 1.0 fresnel on } conserve_energy }
  interior { ior 1.474 } }
