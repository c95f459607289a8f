// benchmark.pov's water normal: a function normal from f_ridged_mf (internal 59) with its
// parameters, bump size 0.2, scale 0.07, under a sharp highlight (exact at 160x120 too).
#version 3.7;
global_settings { assumed_gamma 1 }
#declare f_ridged_mf = function { internal(59) }
#declare RMF = function { f_ridged_mf(x, y, z, 0.07, 2.2, 7, 0.6, 0.9, 1) }
camera { location <0, 1.2, -1.5> look_at <0, 0, 0.5> angle 50 }
light_source { <-3, 5, 4> rgb 1 }
plane { y, 0 pigment { rgb <0.5, 0.6, 0.8> } finish { ambient 0 diffuse 0.6 specular 0.6 roughness 0.01 }
  normal { function { RMF(x, y, z) } 0.2 scale 0.07 } }
