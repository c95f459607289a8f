// conserve_energy with a metallic reflection takes the tinted reflection (green here) from
// what passes, channel by channel, not the untinted amount.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -4> look_at <0, 0.3, 0> }
sky_sphere { pigment { rgb <0.55, 0.65, 1> } }
plane { y, -1 pigment { checker rgb 1 rgb 0.5 } }
box { <-1.5, -0.2, -0.5>, <1.5, 0.2, 0.5> rotate -20*x
  material { texture { pigment { rgbt <0, 1, 0, 1> } finish { ambient 0 diffuse 0 reflection { 0.8 metallic } conserve_energy } } interior { ior 1.3 } } }
