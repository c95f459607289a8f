// An area light with an even number of points per side (4x4, no adaptive) half hidden by a
// wall: across the penumbra the floor takes 1, 3/4, 1/2, 1/4 and 0 of the light, the mean of
// the hidden columns, because the array splits into two halves sharing no point (a 5x5
// array's halves share the middle column). Upper half: a 4x4 light; lower half: 5x5.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 3, -0.001> look_at <0, 0.5, 0> right x*6 up z*4.5 }
light_source { <0, 10, 1.1> rgb 1 area_light 4*x, 2*z, 4, 4 }
light_source { <0, 10, -1.1> rgb 1 area_light 4*x, 2*z, 5, 5 }
box { <-10, 5, -10>, <0, 5.1, 10> pigment { rgb 0 } }
plane { y, 0.5 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
// Keeps each light to its own half.
box { <-10, 0.6, -0.02>, <10, 9, 0.02> pigment { rgb 0 } }
