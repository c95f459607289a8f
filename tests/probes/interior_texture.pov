// interior_texture shades the surface where the ray meets it from inside (a clipped sphere's
// far wall, an open box), also through a union that passes it to members without a texture.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,3,-10> look_at 0 angle 30 }
light_source { <-5,8,-10> rgb 1 }
sphere { <-1.3,0,0>, 1.1 texture { pigment { rgb <0.5,0.4,1> } } interior_texture { pigment { rgb <1,0.7,0> } normal { bumps 0.7 scale 0.15 } }
  clipped_by { box { <-3,0.2,-3>, <3,0.6,3> inverse } } }
union {
  box { <-0.9,-0.9,-0.9>, <0.9,0.9,0.9> }
  sphere { <0,1.2,0>, 0.3 texture { pigment { rgb <0,1,0> } } }
  texture { pigment { rgb 1 filter 0.9 } }
  interior_texture { pigment { rgb <1,0,0> } finish { ambient 0.3 } }
  translate 1.3*x
}
plane { y, -1.2 pigment { checker rgb 0.2, rgb 0.8 } }
