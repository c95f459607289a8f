// Omnimax camera, default right 4/3: the disc's centre sits below the picture's centre and the
// dome's lower edge (45° below the axis) cuts the bottom corners (scripts/measure_omnimax.sh).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { omnimax location <0,1,-2> look_at <0,1.5,2> }
light_source { <3,8,-4> rgb 1 }
background { rgb <0.2,0.3,0.6> }
plane { y, -1 pigment { checker rgb 1 rgb 0.4 } }
#for (i,0,11) sphere { <4*sin(i*pi/6), 0, 4*cos(i*pi/6)>, 0.7 pigment { rgb <mod(i,3)/2, mod(i,4)/3, 1-mod(i,5)/4> } } #end
sphere { <0,4,2>, 1 pigment { rgb <1,1,0> } }
