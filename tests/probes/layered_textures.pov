// Layered textures: each layer lit with its own finish, weighted by what the layers above let
// through; reflections of all layers add; what passes every layer goes through the object.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,2,-6> look_at <0,0.8,0> angle 45 }
light_source { <3,6,-4> rgb 1 }
light_source { <-4,3,-2> rgb 0.4 }
background { rgb <0.3,0.4,0.6> }
plane { y, 0 texture { pigment { checker rgb 1 rgb 0.3 } } texture { pigment { gradient x color_map { [0 rgbt <1,0,0,0.2>] [1 rgbt <0,0,1,1>] } } finish { phong 0.5 } } }
sphere { <-1.2,1,0>, 1 texture { pigment { rgb <1,0.8,0.2> } finish { phong 0.6 reflection 0.2 } } texture { pigment { checker rgbf <0,0.5,1,0.7> rgbt <1,1,1,1> scale 0.3 } finish { specular 0.5 } } }
sphere { <1.2,1,0>, 1 texture { pigment { rgbt <0.2,1,0.2,0.5> } } texture { pigment { rgbt <1,1,1,0.8> } finish { reflection 0.3 } } interior { ior 1.3 } }
