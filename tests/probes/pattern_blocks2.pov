#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,0,-10> look_at 0 angle 26 }
light_source { <-5,8,-10> rgb 1 }
#declare F = finish { ambient 0.4 diffuse 0.6 }
box { <-2.2,0.05,0>, <-0.05,1.7,1> pigment { square scale 0.3 rotate x*90 } finish { F } }
box { <0.05,0.05,0>, <2.2,1.7,1> pigment { triangular pigment { rgb 1 } pigment { rgb 0 } pigment { rgb <1,0,0> } pigment { rgb <0,1,0> } pigment { rgb <0,0,1> } pigment { gradient x scale 0.2 } scale 0.35 rotate x*90 } finish { F } }
box { <-2.2,-1.7,0>, <-0.05,-0.05,1> pigment { mandel 30 scale 0.6 translate <-0.8,-0.9,0> } finish { F } }
sphere { <1.1,-0.9,0>, 0.85 pigment { cubic rotate <20,30,0> translate <1.1,-0.9,0> } finish { F } }
