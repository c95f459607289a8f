// Height fields: 8-bit grey PNG (povray reads some values one lower), 16-bit grey PNG with water_level, a function field; the images were made with PIL.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5,1.6,-1.2> look_at <0.5,0.2,0.5> angle 55 }
light_source { <3,6,-4> rgb 1 }
light_source { <-4,3,-1> rgb 0.3 }
background { rgb <0.2,0.3,0.5> }
height_field { png "hf_hills8.png" pigment { rgb <0.9,0.7,0.4> } scale <0.48,0.4,0.48> }
height_field { png "hf_hills16.png" water_level 0.3 pigment { rgb <0.5,0.8,0.4> } finish { phong 0.4 } scale <0.48,0.4,0.48> translate x*0.52 }
height_field { function 40, 30 { 0.5 + 0.3*sin(x*9)*sin(y*7) } pigment { rgb <0.6,0.6,0.9> } scale <1,0.3,0.45> translate z*0.55 }
plane { y, 0 pigment { checker rgb 0.3 rgb 0.6 scale 0.1 } }
