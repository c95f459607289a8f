#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,0,-3> look_at 0 }
light_source { <0,0,-10> rgb 1 }
background { rgb 0 }
disc { 0, -z, 1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
sphere { <0,0,-5>, 0.5 pigment { rgbf <1,0.5,0.25,0.8> } no_image }
