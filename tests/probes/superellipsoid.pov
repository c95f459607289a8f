// Superellipsoids: rounded box, rounded cylinder, pinched star (e, n > 2) and a flattened one.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,3,-8> look_at 0 angle 50 }
light_source { <4,8,-6> rgb 1 }
background { rgb <0.2,0.3,0.5> }
superellipsoid { <0.25, 0.25> pigment { rgb <1,0.5,0.2> } finish { phong 0.5 } translate <-2.5,0,0> }
superellipsoid { <1, 0.3> pigment { rgb <0.3,0.8,0.3> } rotate <30,20,0> }
superellipsoid { <2.5, 2.5> pigment { rgb <0.3,0.3,1> } finish { phong 0.8 } scale 1.2 translate <2.5,0,0> }
superellipsoid { <0.6, 1.8> pigment { rgb 1 } translate <0,0,3> scale <1,0.5,1> }
