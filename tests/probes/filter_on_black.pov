#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,0,-3> look_at 0 }
background { rgb <0,0,0> }
disc { 0, -z, 1 pigment { rgbf <1,0.5,0.25,0.5> } finish { ambient 1 diffuse 0 } }
