// Colour map entries sharing a value: the earlier one gives the colour there, except at or
// past the last entry's value, where the last entry does: mandel's inside (value 1) is blue
// here, and gradient x's 0.5 and 0.75 take the earlier entry (measured with povray).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -1> look_at 0 right x*8/3 up y*2 }
plane { z, 0 pigment { mandel 50 color_map { [0 rgb 0] [0.5 rgb x] [1 rgb x+y] [1 rgb z] } translate 0.5*x }
  finish { ambient 1 diffuse 0 } clipped_by { plane { y, 0.2 } } }
plane { z, 0 pigment { gradient x color_map { [0 rgb 0] [0.5 rgb x] [0.5 rgb y] [0.75 rgb z] [0.75 rgb <1,1,0>] [1 rgb <0,1,1>] [1 rgb <1,0,1>] } scale 0.4 }
  finish { ambient 1 diffuse 0 } clipped_by { plane { -y, -0.2 } } }
