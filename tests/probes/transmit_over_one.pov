// filter + transmit above 1: the surface's own light is weighted by 1 - filter - transmit
// even when that is negative (advanced/bwstripe.pov's contrast trick), and shadow rays are
// amplified by transmit the same way.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> look_at 0 }
light_source { <0, 0, -20> rgb 0.3 }
sphere { <0, 0, -5>, 0.001 pigment { color rgb 0.5 transmit 1.6 } finish { ambient 1 diffuse 0 } }
box { <-0.5, -2, -3>, <0.5, 2, -2.9> pigment { color rgb 0.5 transmit 2 } finish { ambient 0 diffuse 0 } }
plane { z, 0 pigment { gradient x color_map { [0 rgb 0.3] [1 rgb 0.7] } } finish { ambient 0.3 diffuse 1 } }
