// A light lying on a surface is not shadowed by it (radiosity/cornell's area lights sit on the
// ceiling triangles): povray ignores crossings within ~2.9e-5 of the light. Area light and
// point light, both exactly in the ceiling's plane.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 2, 0> }
triangle { <-6, 4, -6>, <6, 4, -6>, <0, 4, 6> pigment { rgb 1 } }
plane { z, 1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
plane { y, 0 pigment { rgb 0.5 } finish { ambient 0 diffuse 1 } }
box { <-0.5, 0, -1>, <0.5, 1.5, 0> pigment { rgb <1, 0.3, 0.2> } }
light_source { <0, 4, -1> rgb 0.7 area_light 2*x, 2*z, 3, 3 adaptive 0 }
light_source { <1.3, 4, -2.1> rgb 0.4 }
