// area_illumination: each point of a 5x5 array one unit above a plane lights it from its own
// direction with an equal share (the plane's diffuse is the mean of the 25 cosines, no hot
// spot under the centre), while the shadows stay the array's adaptive average.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -0.01> look_at 0 angle 90 }
light_source { <0, 1, 0> rgb 1 area_light 6*x, 6*z, 5, 5 adaptive 1 area_illumination on }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0 diffuse 0.8 specular 0.3 roughness 0.02 } }
sphere { <1.5, 0.3, 1>, 0.3 pigment { rgb <1, 0.3, 0.2> } finish { ambient 0 phong 0.5 } }
