#version 3.7;
global_settings { assumed_gamma 2.2 }
camera { location <0,0,-4> look_at 0 angle 40 }
light_source { <3,4,-5> rgb 1 }
plane { z, 2 pigment { checker rgb <0.9,0.7,0.3> rgb <0.1,0.2,0.5> } }
sphere { 0, 1 pigment { rgb <0.8,0.3,0.2> } finish { phong 0.7 reflection 0.2 } }
