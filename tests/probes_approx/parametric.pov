// parametric: a screw-like surface filling the view, clipped by a sphere container, checker
// uv-mapped on (u, v). lancer draws a 256x256 smooth mesh where povray subdivides per ray.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -3> look_at <0, 0, 0> }
light_source { <3, 5, -6> rgb 1 }
background { rgb 0.2 }
parametric {
  function { u * cos(v) }
  function { 0.15 * v - 0.6 }
  function { u * sin(v) }
  <0.2, 0>, <1.2, 8>
  contained_by { sphere { 0, 1.1 } }
  accuracy 0.001
  precompute 10 x, y, z
  texture { uv_mapping pigment { checker rgb <1, 0.4, 0.2> rgb 0.9 scale <0.25, 0.5, 1> } }
  rotate 20*y
}
