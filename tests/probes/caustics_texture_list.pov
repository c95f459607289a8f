// Fake caustics under a patterned texture: the normal of the texture listed at the point
// (here a checker of bumps and wrinkles) perturbs the caustic's normal (render::shadow).
#version 3.7; global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,5,0> look_at 0 right 4*x up 4*z }
light_source { <0,1000,0> rgb 0.3 parallel point_at 0 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
plane { y, 1 hollow interior { caustics 1 }
  texture { checker
    texture { pigment { rgbf <1,1,1,1> } finish { ambient 0 diffuse 0 } normal { bumps 0.5 scale 0.5 } }
    texture { pigment { rgbf <1,1,1,1> } finish { ambient 0 diffuse 0 } normal { wrinkles 0.6 scale 0.7 } } } }
