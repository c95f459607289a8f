#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,0,-4> look_at 0 angle 40 }
light_source { <3,4,-5> rgb 1 shadowless }
sphere { 0, 1 pigment { rgb <0.8,0.3,0.2> } finish { ambient 0 diffuse 0 phong 1 } }
