// Atmospheric scattering media lit by a narrow spotlight (the beam is found and sampled
// apart from the unlit stretch) and a light with media_interaction off; media_attenuation
// dims the light reaching the floor.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -8> look_at <0, 1.5, 0> }
media { scattering { 1, 0.05 } samples 5 }
plane { y, 0 pigment { rgb 0.6 } finish { ambient 0.1 diffuse 0.8 } }
plane { z, 4 pigment { rgb 0.4 } finish { ambient 0.1 diffuse 0.8 } }
light_source { <0, 6, 0>, rgb 3 spotlight point_at <1, 0, 0> radius 6 falloff 9 media_attenuation on }
light_source { <-5, 5, -5>, rgb 0.3 media_interaction off }
