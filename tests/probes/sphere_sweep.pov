// Sphere sweeps: linear_spline (tubes between spheres of different radii), b_spline and cubic_spline.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.2,3.1,-8.3> look_at <0,0.4,0> angle 50 }
light_source { <-5,9,-6> rgb 1 }
light_source { <6,5,-3> rgb 0.3 }
plane { y, -1.51 pigment { rgb 0.7 } }
#declare F = finish { phong 0.5 }
sphere_sweep { linear_spline 4, <-2.5,0,0>,0.4 <-1,1.5,0.5>,0.6 <1,0,-0.5>,0.3 <2.5,1.8,0.5>,0.7 translate <0,0.3,1.5> pigment { rgb <1,0.5,0.3> } finish { F } }
sphere_sweep { b_spline 6, <-3,-1,0>,0.5 <-2,1.5,1>,0.8 <0,-1,0>,0.3 <1,2,-1>,0.6 <2.5,0,0>,0.4 <3,-2,0>,1.0 scale 0.6 translate <-1.7,0,-1.1> pigment { rgb <0.4,0.9,0.4> } finish { F } }
sphere_sweep { cubic_spline 6, <-3,-1,0>,0.5 <-2,1.5,1>,0.8 <0,-1,0>,0.3 <1,2,-1>,0.6 <2.5,0,0>,0.4 <3,-2,0>,1.0 tolerance 1e-4 scale 0.6 translate <2.1,0.2,-1.3> pigment { rgb <0.4,0.5,1> } finish { F } }
