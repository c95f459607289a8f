// f_hetero_mf and f_ridge (noise-based internal functions) as terrain isosurfaces: lancer
// computes them as povray does (src/func/internal_noise.rs, scripts/compare_internal_functions.py).
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0, 0> angle 50 }
light_source { <-5, 8, -6> rgb 1 }
background { rgb <0.6, 0.7, 0.9> }
isosurface {
  function { y - 0.6 * f_hetero_mf(x, 0, z, 0.6, 2.1, 5.5, 0.4, 1, 2) }
  contained_by { box { <-2, -1.5, -1>, <0, 1.5, 2> } }
  max_gradient 15
  pigment { rgb <0.8, 0.7, 0.5> }
}
isosurface {
  function { y - 0.8 * f_ridge(x, 0, z, 2.2, 4.3, 0.55, 0.3, 0.6, 3) }
  contained_by { box { <0, -1.5, -1>, <2, 1.5, 2> } }
  max_gradient 4
  pigment { rgb <0.5, 0.7, 0.5> }
}
plane { y, -1 pigment { checker rgb 0.3 rgb 0.6 } }
