#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 3 }
camera { location <0,0,-4> look_at 0 angle 40 }

plane { z, 3 pigment { checker rgb 1 rgb <0.2,0.3,0.8> } finish { ambient 1 diffuse 0 } }
sphere { 0, 1 pigment { rgbf 1 } finish { ambient 0 diffuse 0 reflection {0, 1 fresnel on} conserve_energy } interior { ior 1.5 } }
