// A camera normal's pattern is evaluated at (u, v, 0), u and v from -1/2 to 1/2 across the
// picture's width and height, whatever the lengths of right and up (measured with povray).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location 0 direction 2*z right x*2 up y*1.5 normal { bumps 0.4 scale 0.15 } }
plane { -z, -100 pigment { checker rgb 0.2 rgb 0.9 scale 10 } finish { ambient 1 diffuse 0 } }
