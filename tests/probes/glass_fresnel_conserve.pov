#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,0,-4> look_at 0 angle 40 }
light_source { <3,4,-5> rgb 1 }
plane { z, 3 pigment { checker rgb 1 rgb <0.2,0.3,0.8> } }
sphere { 0, 1 pigment { rgbf <0.98,1,0.99,0.95> } finish { ambient 0 diffuse 0 reflection {0, 1 fresnel on} conserve_energy } interior { ior 1.474 } }
