// A perturbed normal can send a reflection into the surface; POV-Ray mirrors it back out
// across the true surface (measured: a sky coloured by direction, see docs/povray-behaviour.md).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -8> look_at <0, 0, 20> angle 55 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0, 0, 0.6>] [1 rgb 1] } } }
plane { y, 0 texture { pigment { rgb 0 } normal { bumps 1 scale 0.5 } finish { ambient 0 diffuse 0 reflection 1 } } }
