// f_helix1, f_helix2, f_spiral and polynomial internal functions (f_steiners_roman,
// f_torus_gumdrop) as isosurfaces: lancer computes them as povray does (src/func/internal_*).
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -9> look_at <0, 0, 0> angle 50 }
light_source { <-20, 30, -40> rgb 1 }
background { rgb <0.1, 0.2, 0.3> }
isosurface {
  function { f_helix1(x, y, z, 3, 3.5, 0.2, 0.55, 2, 1, 0) }
  contained_by { box { <-1, -3, -1>, <1, 3, 1> } }
  max_gradient 2.6
  translate -2.6 * x
  pigment { rgb <1, 0.8, 0.6> }
}
isosurface {
  function { f_helix2(x, y, z, 0, 3, 0.35, 0.4, 0, 0.5, 0) }
  contained_by { box { <-1, -3, -1>, <1, 3, 1> } }
  max_gradient 3
  translate -0.8 * x
  pigment { rgb <0.6, 0.6, 1> }
}
isosurface {
  function { f_spiral(x, y, z, 0.3, 0.06, 1.4, 0, 0, 1) }
  contained_by { box { <-1.4, -0.1, -1.4>, <1.4, 0.1, 1.4> } }
  max_gradient 3
  rotate -70 * x translate <1.9, 1.3, 0>
  pigment { rgb <0.6, 1, 0.6> }
}
isosurface {
  function { f_steiners_roman(x, y, z, -1) }
  contained_by { sphere { 0, 1.2 } }
  max_gradient 3
  rotate <30, 40, 0> translate <1.9, -1.4, 0>
  pigment { rgb <1, 0.6, 0.6> }
}
