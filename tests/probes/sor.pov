// Surfaces of revolution: the manual's vase closed, the same open and tilted so its inside shows.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.3,5.2,-8.9> look_at <0,1,0> angle 45 }
light_source { <-5,9,-6> rgb 1 }
light_source { <6,5,-3> rgb 0.3 }
plane { y, -0.01 pigment { rgb 0.7 } }
#declare F = finish { phong 0.5 }
#declare Vase = sor { 7, <0.000000, 0.000000> <0.118143, 0.000000> <0.620253, 0.540084> <0.210970, 0.827004> <0.194093, 0.962025> <0.286920, 1.000000> <0.468354, 1.033755> }
object { Vase scale 2.7 translate x*-1.5 pigment { rgb <0.9,0.7,0.4> } finish { F } }
sor { 7, <0.000000, 0.000000> <0.118143, 0.000000> <0.620253, 0.540084> <0.210970, 0.827004> <0.194093, 0.962025> <0.286920, 1.000000> <0.468354, 1.033755> open
  scale 2.7 rotate x*-33 translate <1.6,0.4,0> pigment { rgb <0.4,0.9,0.7> } finish { F } }
