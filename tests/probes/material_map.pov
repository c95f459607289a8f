// material_map: a palette image's pixel index picks a listed texture (mapped like an image
// map onto the x-y unit square; nearest pixel). Indices past the list's end (this image has
// indices up to 240) wrap around the list (measured here).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 0.5, -2.2> look_at <0.5, 0.5, 0> angle 35 }
light_source { <-3, 4, -6> color 1 }
plane { z, 0
  texture {
    material_map { png "hf_palette.png"
      texture { pigment { rgb <1, 0.2, 0.1> } }
      texture { pigment { rgb <0.1, 0.8, 0.2> } finish { phong 0.8 } }
      texture { pigment { gradient x color_map { [0 rgb <0.1, 0.2, 1>] [1 rgb 1] } scale 0.1 } }
    }
    rotate 5*z
  }
}
