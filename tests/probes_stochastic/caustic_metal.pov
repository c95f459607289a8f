// Reflective caustics: a curved mirror (a half cylinder) focuses a point light's photons onto
// a floor; with jitter 0, as in povray's own sample scenes (tests/stochastic_probes.rs).
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.01 jitter 0 } }
camera { location <0, 5, -3> look_at <0, 0, 0.5> angle 50 }
light_source { <0, 3, -4> rgb 1 }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.05 diffuse 0.7 } }
difference {
  cylinder { <0, 0, 1>, <0, 1, 1>, 1.5 }
  cylinder { <0, -1, 1>, <0, 2, 1>, 1.45 }
  box { <-2, -1, -1>, <2, 2, 1> }
  pigment { rgb 0.9 } finish { ambient 0 diffuse 0 reflection { 0.9 metallic } }
  photons { target reflection on collect off }
}
