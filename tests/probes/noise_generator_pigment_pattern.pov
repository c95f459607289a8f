// pigment_pattern and function { pattern } take the scene's noise_generator (1 here), as
// POV-Ray measures; they used to fall back to generator 2 (incdemo/func_gradient 0.41).
#version 3.7;
global_settings { assumed_gamma 1.0 noise_generator 1 }
#declare F = function { pattern { agate scale 0.8 } }
camera { orthographic location <0, 0, -1> look_at 0 right 1.33 * x up y }
#default { finish { ambient 1 diffuse 0 } }
plane { z, 0
  texture {
    pigment { pigment_pattern { agate scale 0.8 } color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } }
  }
  clipped_by { plane { x, 0 } }
}
plane { z, 0
  texture { pigment { function { F(x, y, z) } color_map { [0 rgb 0] [1 rgb <0, 0.5, 1>] } } }
  clipped_by { plane { -x, 0 } }
}
